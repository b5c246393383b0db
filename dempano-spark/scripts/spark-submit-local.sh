#!/usr/bin/env bash
# Runs the job jar the way spark-submit does (org.apache.spark.deploy.SparkSubmit, Spark's own jars
# first on the classpath, the job jar added by Spark), on a machine without a Spark distribution:
# Spark's jars are the ones Gradle resolved for dempano-spark. Local mode by default.
#   dempano-spark/scripts/spark-submit-local.sh [--master local[2]] VIEWPOINTS --out-dir D --dem-dir DIR [options]
# With a Spark 3.5 (Scala 2.13) distribution, use its bin/spark-submit instead (docs/spark.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
master="local[2]"
if [ "${1:-}" = "--master" ]; then master="$2"; shift 2; fi
gradle -q :dempano-spark:jobJar >/dev/null
jar=$(ls dempano-spark/build/libs/dempano-spark-*-job.jar | head -1)
cp=$(gradle -q :dempano-spark:sparkClasspath | tail -1)
# The JVM flags Spark 3.5's launcher adds on Java 17 (JavaModuleOptions).
opens="-XX:+IgnoreUnrecognizedVMOptions"
for p in java.lang java.lang.invoke java.lang.reflect java.io java.net java.nio java.util java.util.concurrent \
         java.util.concurrent.atomic sun.nio.ch sun.nio.cs sun.security.action sun.util.calendar; do
    opens="$opens --add-opens=java.base/$p=ALL-UNNAMED"
done
exec java ${SPARK_DRIVER_MEMORY:+-Xmx$SPARK_DRIVER_MEMORY} $opens -Djdk.reflect.useDirectMethodHandle=false \
    -cp "$cp" org.apache.spark.deploy.SparkSubmit --master "$master" --class dempano.spark.SparkBatchMain \
    --conf spark.ui.enabled=false "$jar" "$@"
