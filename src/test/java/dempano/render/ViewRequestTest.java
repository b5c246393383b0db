package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.panorama.DepthMode;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.ViewLayout;
import dempano.render.OffscreenRenderer.ViewRequest;
import dempano.render.OffscreenRenderer.ViewRequest.Option;
import java.util.EnumSet;
import org.junit.jupiter.api.Test;

/** {@link ViewRequest}'s options: what each render reads back and how it draws. No GL needed. */
class ViewRequestTest {
    private static final ViewLayout LAYOUT = ViewLayout.forPanorama(PanoramaGeometry.of(4, -10, 10), 8, 1);

    @Test
    void theDefaultReadsColourAndTheModesDepthOnly() {
        ViewRequest shader = ViewRequest.of(LAYOUT, DepthMode.SHADER_RANGE, 1, 1000);
        assertEquals(EnumSet.of(Option.COLOUR, Option.RANGE_TARGET), shader.options());
        assertTrue(shader.colour() && shader.rangeTarget());
        assertFalse(shader.surfaces() || shader.release() || shader.drawBackFaces());
        ViewRequest reversed = ViewRequest.of(LAYOUT, DepthMode.REVERSED_32F, 1, 1000);
        assertEquals(EnumSet.of(Option.COLOUR), reversed.options());
    }

    @Test
    void anOptionAddedKeepsTheOthersAndTheRequestIsUnchanged() {
        ViewRequest r = ViewRequest.of(LAYOUT, DepthMode.SHADER_RANGE, 1, 1000);
        ViewRequest all = r.with(Option.SURFACES).with(Option.RELEASE).withBackFaces();
        assertEquals(EnumSet.allOf(Option.class), all.options());
        assertTrue(all.surfaces() && all.release() && all.drawBackFaces() && all.colour() && all.rangeTarget());
        assertEquals(EnumSet.of(Option.COLOUR, Option.RANGE_TARGET), r.options(), "with() makes a new request");
        assertThrows(UnsupportedOperationException.class, () -> r.options().add(Option.RELEASE));
        // The caller's set is copied: changing it later changes no request.
        EnumSet<Option> mine = EnumSet.of(Option.RANGE_TARGET);
        ViewRequest distancesOnly = new ViewRequest(LAYOUT, DepthMode.SHADER_RANGE, 1, 1000, mine);
        mine.add(Option.COLOUR);
        assertFalse(distancesOnly.colour());
    }

    @Test
    void theShaderRangeModeNeedsTheRangeTarget() {
        assertThrows(IllegalArgumentException.class,
                () -> new ViewRequest(LAYOUT, DepthMode.SHADER_RANGE, 1, 1000, EnumSet.of(Option.COLOUR)));
        assertEquals(EnumSet.noneOf(Option.class),
                new ViewRequest(LAYOUT, DepthMode.STANDARD_24, 1, 1000, EnumSet.noneOf(Option.class)).options());
    }
}
