package dempano.render;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.math.Vector3f;

/** The terrain material ({@code dempano/shaders/Terrain.j3md}) as panoramas and the fly-through use it. */
public final class TerrainMaterial {
    private TerrainMaterial() {
    }

    /**
     * Shaded relief lit from the north-west, 40° high, with haze over {@code max(20 km, 0.6 · range)}.
     *
     * @param rangeMetres fragments farther than this horizontally from the origin are discarded
     */
    public static Material create(AssetManager assets, double rangeMetres) {
        Material m = new Material(assets, "dempano/shaders/Terrain.j3md");
        m.setFloat("RangeMetres", (float) rangeMetres);
        m.setFloat("HazeMetres", (float) Math.max(20_000, rangeMetres * 0.6));
        // Sun direction in jME axes (east, up, south).
        double sunAz = Math.toRadians(315), sunEl = Math.toRadians(40);
        m.setVector3("SunDirection", new Vector3f((float) (Math.cos(sunEl) * Math.sin(sunAz)), (float) Math.sin(sunEl),
                (float) (-Math.cos(sunEl) * Math.cos(sunAz))));
        return m;
    }
}
