package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** {@link HgtTile#contentHash()}: the same heights, the same fingerprint; any sample changed, another. */
class HgtTileContentHashTest {
    private static final int N = 121;
    private static final TileId ID = TileId.of(46, 8);

    private static float[] heights(boolean whole) {
        float[] h = new float[N * N];
        for (int i = 0; i < h.length; i++) {
            h[i] = (float) (1500 + 700 * Math.sin(i * 0.013) + (whole ? 0 : 0.25));
            h[i] = whole ? Math.round(h[i]) : h[i];
        }
        return h;
    }

    @Test
    void theSameHeightsGiveTheSameFingerprintWhateverTheObject() {
        for (boolean whole : new boolean[] {true, false}) {
            HgtTile a = HgtTile.of(ID, N, heights(whole), "a"), b = HgtTile.of(ID, N, heights(whole), "another source");
            assertEquals(a.contentHash(), b.contentHash());
            assertEquals(a.contentHash(), a.contentHash(), "kept");
            assertEquals(a.contentHash(), a.withVerticalDatum("EGM2008").contentHash(), "the datum is not the heights");
        }
    }

    @Test
    void anySampleChangedChangesTheFingerprint() {
        Set<Long> seen = new HashSet<>();
        for (boolean whole : new boolean[] {true, false}) {
            float[] base = heights(whole);
            seen.add(HgtTile.of(ID, N, base, "s").contentHash());
            // One sample up by a metre, a centimetre, or two samples swapped: each tile's own fingerprint.
            for (int i : new int[] {0, 1, N * N / 2, N * N - 1}) {
                float[] h = base.clone();
                h[i] += 1;
                seen.add(HgtTile.of(ID, N, h, "s").contentHash());
                if (!whole) {
                    h = base.clone();
                    h[i] += 0.01f;
                    seen.add(HgtTile.of(ID, N, h, "s").contentHash());
                }
                h = base.clone();
                int j = (i + 7) % h.length;
                float t = h[i];
                h[i] = h[j];
                h[j] = t;
                seen.add(HgtTile.of(ID, N, h, "s").contentHash());
            }
        }
        assertEquals(2 + 2 * 4 * 2 + 4, seen.size(), "every variant has its own fingerprint");
    }

    @Test
    void aFilledVoidIsNotTheHeightItWasFilledWith() {
        float[] h = heights(false);
        h[N * 60 + 60] = Float.NaN; // a void, filled on construction
        HgtTile withVoid = HgtTile.of(ID, N, h, "s");
        float[] filled = h.clone();
        filled[N * 60 + 60] = withVoid.heightMetres(60, 60);
        HgtTile plain = HgtTile.of(ID, N, filled, "s");
        assertEquals(withVoid.heightMetres(60, 60), plain.heightMetres(60, 60));
        assertNotEquals(withVoid.contentHash(), plain.contentHash(), "the same heights, one marked as a filled void");
    }
}
