package dempano.render;

import com.jme3.material.Material;
import com.jme3.scene.Geometry;
import dempano.SharedData;
import dempano.dem.DemDirectory;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.DepthMode;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.ViewLayout;
import dempano.terrain.EyePlacement;
import dempano.terrain.TerrainBuilder;

/**
 * Test fixture: a real scene of ../shared/dem as the views of a 10 px/° panorama (−15…15°, 8 views) see it, its
 * terrain built for an eye above the DEM with standard refraction, and the request that draws it with distances
 * only, the shader's range and the triangle names read back.
 *
 * @param terrain the scene, with the distance-only material set on every geometry once {@link #drawnBy} ran
 */
record RealSceneViews(Viewpoint eye, Refraction refraction, double rangeMetres, TerrainBuilder.Terrain terrain,
                      ViewLayout layout, OffscreenRenderer.ViewRequest request) {
    static final double PIXELS_PER_DEGREE = 10;

    static RealSceneViews of(double lat, double lon, double eyeHeightMetres, double rangeMetres) {
        Mosaic mosaic = Mosaic.around(new DemDirectory(SharedData.demDir()), lat, lon, rangeMetres,
                MissingTilePolicy.SEA_LEVEL);
        Viewpoint eye = Viewpoint.onDem(mosaic, lat, lon, 0, eyeHeightMetres);
        Refraction refraction = new Refraction(0.13);
        TerrainBuilder.Terrain terrain = TerrainBuilder.build(mosaic, eye, refraction, rangeMetres, null,
                TerrainBuilder.Detail.of(PIXELS_PER_DEGREE, 0.5));
        ViewLayout layout = ViewLayout.forPanorama(PanoramaGeometry.of(PIXELS_PER_DEGREE, -15, 15), 8, 1);
        OffscreenRenderer.ViewRequest request = new OffscreenRenderer.ViewRequest(layout, DepthMode.SHADER_RANGE, 1,
                rangeMetres * 1.1 + 20_000, java.util.EnumSet.of(OffscreenRenderer.ViewRequest.Option.RANGE_TARGET,
                OffscreenRenderer.ViewRequest.Option.SURFACES));
        return new RealSceneViews(eye, refraction, rangeMetres, terrain, layout, request);
    }

    /** Sets a distance-only terrain material of {@code gl}, placed for the eye, on every geometry; returns this. */
    RealSceneViews drawnBy(OffscreenRenderer gl) {
        Material material = gl.newTerrainMaterial(rangeMetres);
        material.setBoolean("DistanceOnly", true);
        TerrainBuilder.applyEye(material, new EyePlacement(eye, refraction));
        for (Geometry g : terrain.drawn()) {
            g.setMaterial(material);
        }
        return this;
    }
}
