package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dempano.dem.MissingTilePolicy;
import org.junit.jupiter.api.Test;

/** The value each policy writes (fly hands it to its panorama process) is read back as that policy. */
class MissingTilesFlagTest {
    @Test
    void everyPolicysFlagValueReadsBackAsIt() {
        for (MissingTilePolicy p : MissingTilePolicy.values()) {
            assertEquals(p, RenderOptions.missingTilePolicy(p.flagValue()), p.flagValue());
        }
    }
}
