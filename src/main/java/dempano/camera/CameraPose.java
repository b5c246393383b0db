package dempano.camera;

import dempano.dem.Mosaic;
import dempano.dem.TileSelection;
import dempano.geo.Viewpoint;

/**
 * Where a camera is and which way it points. The position follows {@link dempano.PanoramaRequest} and
 * {@link Viewpoint}: the camera stands either on the DEM at the coordinate corrected by a signed offset, or at
 * an explicit absolute altitude, and is {@code cameraHeightMetres} above that standing altitude.
 *
 * @param latDeg             latitude, degrees, [−90, 90]
 * @param lonDeg             longitude, degrees, [−180, 180]
 * @param offsetMetres       signed correction added to the DEM height at the coordinate, metres (0 = on the DEM);
 *                           ignored when {@code altitudeMetres} is given
 * @param altitudeMetres     absolute standing altitude, metres above sea level (the DEM's vertical datum, EGM96
 *                           for SRTM; EXIF GPSAltitude is taken as the same); NaN = from the DEM plus the offset
 * @param cameraHeightMetres the camera above the standing altitude, metres, ≥ 0 (the panorama's eye height: 2 m
 *                           for a photographer standing on the DEM; 0 when the altitude is the camera's own, as
 *                           a GPS altitude is)
 * @param orientation        which way the camera points
 */
public record CameraPose(double latDeg, double lonDeg, double offsetMetres, double altitudeMetres,
                         double cameraHeightMetres, CameraOrientation orientation) {
    public CameraPose {
        TileSelection.checkCoordinates(latDeg, lonDeg);
        if (!Double.isFinite(offsetMetres) || Math.abs(offsetMetres) > 1e6) {
            throw new IllegalArgumentException("offset must be a finite number of metres within ±1e6, got " + offsetMetres);
        }
        if (!Double.isNaN(altitudeMetres) && !(Math.abs(altitudeMetres) < 1e6)) {
            throw new IllegalArgumentException("altitude must be a number of metres within ±1e6 (above sea level), or NaN (from the DEM), got "
                    + altitudeMetres);
        }
        if (!(cameraHeightMetres >= 0 && cameraHeightMetres < 1e6)) {
            throw new IllegalArgumentException("camera height must be a number of metres in [0, 1e6), got " + cameraHeightMetres);
        }
        if (orientation == null) {
            throw new IllegalArgumentException("camera orientation must be given");
        }
    }

    /** Whether the altitude is absolute (true) or the DEM's plus the offset (false). */
    public boolean absoluteAltitude() {
        return !Double.isNaN(altitudeMetres);
    }

    /**
     * The viewpoint this pose stands for on a DEM: {@link Viewpoint#atAltitude} for an absolute altitude,
     * {@link Viewpoint#onDem} otherwise, with the camera height as the eye height.
     *
     * @throws IllegalArgumentException when the mosaic has no height at the coordinate or the camera would be
     *                                  below the DEM surface (the message names the point)
     */
    public Viewpoint viewpoint(Mosaic mosaic) {
        return absoluteAltitude()
                ? Viewpoint.atAltitude(mosaic, latDeg, lonDeg, altitudeMetres, cameraHeightMetres)
                : Viewpoint.onDem(mosaic, latDeg, lonDeg, offsetMetres, cameraHeightMetres);
    }
}
