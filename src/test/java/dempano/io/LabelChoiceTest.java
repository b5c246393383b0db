package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.io.SummitWriter.LabelOrder;
import dempano.summits.Summit;
import dempano.summits.SummitSighting;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Label density: spacing (across the 360° seam too), the limit, and the order that wins. */
class LabelChoiceTest {
    static SummitSighting at(String name, double x, double y, double elevation, double angle, double slant, boolean visible) {
        return new SummitSighting(new Summit(name, 46, 8, elevation), x / 20, angle, x, y, slant, slant, slant, slant, visible);
    }

    static List<String> names(List<SummitSighting> l) {
        return l.stream().map(s -> s.summit().name()).toList();
    }

    @Test
    void spacingLimitAndOrderTable() {
        List<SummitSighting> s = List.of(
                at("A", 100, 50, 4000, 1.0, 30_000, true),
                at("B", 110, 50, 3500, 3.0, 5_000, true),   // 10 px from A
                at("C", 7195, 50, 3800, 0.5, 60_000, true), // 105 px from A across the seam
                at("D", 500, 50, 4500, 0.2, 90_000, false), // hidden: never labelled
                at("E", 300, 2000, 4600, -9, 1_000, true),  // below the picture: never labelled
                at("F", 900, 50, 3000, 2.0, 8_000, true));
        // {order, spacing, max, expected}
        Object[][] table = {
                {LabelOrder.HEIGHT, 18.0, 0, List.of("A", "C", "F")},            // B is 10 px from A
                {LabelOrder.HEIGHT, 200.0, 0, List.of("A", "F")},           // C is 105 px from A around the seam
                {LabelOrder.HEIGHT, 18.0, 2, List.of("A", "C")},
                {LabelOrder.ANGLE, 8.0, 0, List.of("B", "F", "A", "C")},
                {LabelOrder.ANGLE, 50.0, 0, List.of("B", "F", "C")},         // A is 10 px from B
                {LabelOrder.DISTANCE, 50.0, 3, List.of("B", "F", "C")},
        };
        for (Object[] row : table) {
            List<SummitSighting> got = SummitWriter.chooseLabels(s, 7200, 1200, (Double) row[1], (Integer) row[2], (LabelOrder) row[0]);
            assertEquals(row[3], names(got), row[0] + " spacing " + row[1] + " max " + row[2]);
        }
    }

    @Test
    void hundredsOfCompetingSummitsKeepTheirSpacing() {
        Random rnd = new Random(3);
        List<SummitSighting> many = new ArrayList<>();
        for (int i = 0; i < 600; i++) {
            many.add(at("S" + i, rnd.nextDouble() * 7200, 300, 1000 + rnd.nextDouble() * 3000, 1, 10_000, true));
        }
        List<SummitSighting> got = SummitWriter.chooseLabels(many, 7200, 1200, 40, 0, LabelOrder.HEIGHT);
        assertTrue(got.size() <= 180 && got.size() > 60, "labels: " + got.size());
        for (SummitSighting a : got) {
            for (SummitSighting b : got) {
                double dx = Math.abs(a.pixelX() - b.pixelX());
                assertTrue(a == b || Math.min(dx, 7200 - dx) >= 40, a + " and " + b);
            }
        }
        assertEquals(25, SummitWriter.chooseLabels(many, 7200, 1200, 40, 25, LabelOrder.HEIGHT).size());
    }

    @Test
    void badOptionsAreClearErrors() {
        assertThrows(IllegalArgumentException.class, () -> new SummitWriter.LabelOptions(-1, Double.NaN, LabelOrder.HEIGHT));
        assertThrows(IllegalArgumentException.class, () -> new SummitWriter.LabelOptions(0, -3, LabelOrder.HEIGHT));
    }

    /** The camera overlay's labels: highest first, none overlapping, inside the image, only visible summits. */
    @Test
    void cameraOverlayLabelsDoNotOverlap() {
        List<SummitSighting> s = List.of(
                at("Low", 100, 100, 2000, 1, 5000, true), at("High", 102, 101, 3000, 1, 5000, true),
                at("Mid", 101, 99, 2500, 1, 5000, true), at("Far", 400, 200, 2200, 1, 5000, true),
                at("Edge", 590, 300, 2100, 1, 5000, true), at("Hidden", 250, 250, 4000, 1, 5000, false));
        List<CameraWriter.Label> labels = CameraWriter.labels(s, t -> 7 * t.length(), 10, 3, 600, 400);
        List<String> placed = labels.stream().map(l -> l.text().split(" ")[0]).toList();
        // Of the three piled up at (100, 100) the highest is labelled; the others are clear of everything; the hidden one
        // is not labelled.
        assertEquals(List.of("High", "Far", "Edge"), placed);
        for (int i = 0; i < labels.size(); i++) {
            CameraWriter.Label a = labels.get(i);
            int aw = 7 * a.text().length();
            assertTrue(a.x() >= 0 && a.x() + aw <= 600 && a.baseline() - 10 >= 0, a.toString());
            for (int j = i + 1; j < labels.size(); j++) {
                CameraWriter.Label b = labels.get(j);
                int bw = 7 * b.text().length();
                boolean apart = a.x() + aw <= b.x() || b.x() + bw <= a.x() || a.baseline() + 3 <= b.baseline() - 10
                        || b.baseline() + 3 <= a.baseline() - 10;
                assertTrue(apart, a + " and " + b);
            }
        }
        // The one at the right edge reads leftwards from its ring.
        assertTrue(labels.get(2).x() < 590, labels.get(2).toString());
    }
}
