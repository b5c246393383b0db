package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Every triangle ends with a vertex of its own that names it, and is otherwise the triangle it was. */
class ProvokingVerticesTest {
    /** A cs × cs grid split as {@link Triangulation} says, with the corner order TerrainBuilder uses. */
    static int[] diamondGrid(int cs) {
        int[] idx = new int[(cs - 1) * (cs - 1) * 6];
        int at = 0;
        for (int i = 0; i < cs - 1; i++) {
            for (int j = 0; j < cs - 1; j++) {
                int nw = i * cs + j, ne = nw + 1, sw = nw + cs, se = sw + 1;
                int[] two = Triangulation.splitsNorthWestToSouthEast(i, j)
                        ? new int[] {se, ne, nw, nw, sw, se} : new int[] {sw, se, ne, sw, ne, nw};
                System.arraycopy(two, 0, idx, at, 6);
                at += 6;
            }
        }
        return idx;
    }

    static void checkAssignment(int[] indices, int vertexCount, ProvokingVertices pv) {
        Set<Integer> provokers = new HashSet<>();
        for (int t = 0; t < indices.length / 3; t++) {
            int o = 3 * t;
            assertEquals(indices[o], pv.indices()[o]);
            assertEquals(indices[o + 1], pv.indices()[o + 1]);
            int last = pv.indices()[o + 2];
            assertEquals(indices[o + 2], pv.source()[last], "triangle " + t + " ends with its own last vertex or a copy");
            assertEquals(t, (int) pv.provokedTriangle()[last], "triangle " + t + "'s provoking vertex names it");
            assertTrue(provokers.add(last), "vertex " + last + " provokes two triangles");
        }
        int named = 0;
        for (float f : pv.provokedTriangle()) {
            named += f >= 0 ? 1 : 0;
        }
        assertEquals(indices.length / 3, named, "only provoking vertices name a triangle");
        for (int v = 0; v < vertexCount; v++) {
            assertEquals(v, pv.source()[v], "the original vertices keep their places");
        }
    }

    @Test
    void aDiamondGridNeedsAboutTwiceItsVertices() {
        int cs = 65;
        int[] indices = diamondGrid(cs);
        ProvokingVertices pv = ProvokingVertices.assign(indices, cs * cs);
        checkAssignment(indices, cs * cs, pv);
        // Counted by hand: with the last corners nw, se (even cells) and ne, nw (odd), vertex (a, b)
        // ends 3 triangles where a + b is even and it has a cell to its south-east, 1 otherwise.
        int expected = 0;
        for (int a = 0; a < cs; a++) {
            for (int b = 0; b < cs; b++) {
                int ends = (a < cs - 1 && b < cs - 1 ? 1 : 0)                                  // nw of its own cell
                        + (a > 0 && b > 0 && ((a + b) & 1) == 0 ? 1 : 0)                       // se of an even cell
                        + (a < cs - 1 && b > 0 && ((a + b - 1) & 1) == 1 ? 1 : 0);             // ne of an odd cell
                expected += Math.max(1, ends);
            }
        }
        assertEquals(expected, pv.vertexCount());
        assertTrue(pv.vertexCount() < 2.1 * cs * cs, pv.vertexCount() + " vertices");
    }

    @Test
    void attributesFollowTheirVertexAndBadMeshesAreRefused() {
        int[] indices = {0, 1, 2, 2, 1, 3, 3, 1, 2};
        ProvokingVertices pv = ProvokingVertices.assign(indices, 4);
        checkAssignment(indices, 4, pv);
        float[] xy = {0, 0, 1, 0, 0, 1, 1, 1};
        float[] copied = pv.copy(xy, 2);
        for (int v = 0; v < pv.vertexCount(); v++) {
            assertEquals(xy[2 * pv.source()[v]], copied[2 * v]);
            assertEquals(xy[2 * pv.source()[v] + 1], copied[2 * v + 1]);
        }
        assertEquals(5, pv.vertexCount()); // vertex 2 ends triangles 0 and 2
        assertThrows(IllegalArgumentException.class, () -> ProvokingVertices.assign(new int[] {0, 1, 4}, 4));
    }
}
