#!/usr/bin/env bash
# Installs what a fresh Debian machine lacks to build, test and run dempano:
# Java 17, Gradle (Debian's 4.4.1 works), Mesa's software OpenGL (llvmpipe) with EGL for headless
# rendering, Xvfb for the on-screen fly-through without a display, and GDAL's command-line tools
# (gdal-bin), with which the tests make GeoTIFFs in every layout from the shared .hgt tiles.
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
    openjdk-17-jdk-headless gradle \
    libegl1 libegl-mesa0 libgl1 libgl1-mesa-dri libglx-mesa0 \
    xvfb xauth gdal-bin >/dev/null
java -version 2>&1 | head -1
gradle --version 2>/dev/null | grep '^Gradle'
gdal_translate --version
