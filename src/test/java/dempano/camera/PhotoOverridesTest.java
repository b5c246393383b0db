package dempano.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;

/** The overrides' groups: each {@code with…} sets its own value and no other. */
class PhotoOverridesTest {
    @Test
    void eachWithSetsItsOwnValueAndNoOther() {
        Map<String, Function<PhotoOverrides, Object>> values = new LinkedHashMap<>();
        values.put("lat", PhotoOverrides::latDeg);
        values.put("lon", PhotoOverrides::lonDeg);
        values.put("altitude", PhotoOverrides::altitudeMetres);
        values.put("offset", PhotoOverrides::offsetMetres);
        values.put("cameraHeight", PhotoOverrides::cameraHeightMetres);
        values.put("heading", PhotoOverrides::headingDeg);
        values.put("declination", PhotoOverrides::declinationDeg);
        values.put("pitch", PhotoOverrides::pitchDeg);
        values.put("roll", PhotoOverrides::rollDeg);
        values.put("focal", PhotoOverrides::focalLengthMm);
        values.put("sensorWidth", PhotoOverrides::sensorWidthMm);
        values.put("focal35", PhotoOverrides::focal35mmMm);
        values.put("hfov", PhotoOverrides::horizontalFovDeg);
        values.put("distortion", PhotoOverrides::distortion);
        values.put("calibration", PhotoOverrides::calibration);
        Map<String, UnaryOperator<PhotoOverrides>> changes = new LinkedHashMap<>();
        changes.put("lat", o -> o.withPosition(46.4, o.lonDeg()));
        changes.put("lon", o -> o.withPosition(o.latDeg(), 8.1));
        changes.put("altitude", o -> o.withAltitudeMetres(2900));
        changes.put("offset", o -> o.withOffsetMetres(-3));
        changes.put("cameraHeight", o -> o.withCameraHeightMetres(1.6));
        changes.put("heading", o -> o.withHeadingDeg(123));
        changes.put("declination", o -> o.withDeclinationDeg(2.5));
        changes.put("pitch", o -> o.withPitchDeg(-4));
        changes.put("roll", o -> o.withRollDeg(1.5));
        changes.put("focal", o -> o.withFocalLengthMm(24));
        changes.put("sensorWidth", o -> o.withSensorWidthMm(23.5));
        changes.put("focal35", o -> o.withFocal35mmMm(36));
        changes.put("hfov", o -> o.withHorizontalFovDeg(54));
        changes.put("distortion", o -> o.withDistortion(LensDistortion.radial(-0.1, 0.01, 0)));
        changes.put("calibration", o -> o.withCalibration(CameraIntrinsics.fromHorizontalFov(600, 400, 50)));
        assertEquals(values.keySet(), changes.keySet());
        // From nothing given, and from everything given (each change then replaces a value).
        PhotoOverrides all = PhotoOverrides.NONE;
        for (UnaryOperator<PhotoOverrides> c : changes.values()) {
            all = c.apply(all);
        }
        PhotoOverrides other = all.withPosition(-33, 151).withAltitudeMetres(10).withOffsetMetres(1).withCameraHeightMetres(3)
                .withHeadingDeg(5).withDeclinationDeg(-1).withPitchDeg(2).withRollDeg(-2).withFocalLengthMm(50)
                .withSensorWidthMm(36).withFocal35mmMm(50).withHorizontalFovDeg(40).withDistortion(LensDistortion.NONE)
                .withCalibration(CameraIntrinsics.fromHorizontalFov(300, 200, 40));
        for (PhotoOverrides base : new PhotoOverrides[] {PhotoOverrides.NONE, other}) {
            for (Map.Entry<String, UnaryOperator<PhotoOverrides>> change : changes.entrySet()) {
                PhotoOverrides changed = change.getValue().apply(base);
                for (Map.Entry<String, Function<PhotoOverrides, Object>> value : values.entrySet()) {
                    Object before = value.getValue().apply(base), after = value.getValue().apply(changed);
                    if (value.getKey().equals(change.getKey())) {
                        assertNotEquals(before, after, change.getKey() + " set");
                    } else {
                        assertEquals(before, after, "with " + change.getKey() + ": " + value.getKey() + " kept");
                    }
                }
            }
        }
    }
}
