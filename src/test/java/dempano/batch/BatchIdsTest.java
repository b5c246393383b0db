package dempano.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class BatchIdsTest {
    /** Two ids, and the file name both would write ('' where none). */
    @ParameterizedTest(name = "{0} / {1}")
    @CsvSource({
        "a, a-distance, a-distance.png",
        "a-distance, a, a-distance.png",
        "a, A-DISTANCE, a-distance.png",
        "p, p-summits, p-summits.json",
        "p, p-labels, p-labels.png",
        "p, p-overlay, p-overlay.png",
        "p, p-orientation, p-orientation.png",
        "a, a-1, ''",
        "a, a-dist, ''",
        "a, ab, ''",
        "a, a.png, ''",
        "x, x-elevation, ''",
        "v01, v02, ''"})
    void idsWhoseFilesWouldShareANameClash(String one, String other, String shared) {
        String found = BatchIds.clashingIds(other).getOrDefault(BatchIds.collisionKey(one), "");
        assertEquals(shared, found);
    }
}
