package dempano.batch;

import dempano.camera.PhotoOverrides;
import dempano.orient.SearchRanges;
import java.nio.file.Path;
import java.util.Objects;

/**
 * The photograph of a photo row: its file and the values the row's columns give for its camera, which
 * override (or stand in for) the photo's EXIF/XMP. The row is rendered on the photo's own pixel grid by
 * {@link dempano.photo.PhotoJob}, as {@code dempano photo} renders it.
 *
 * @param image     the photograph (JPEG, PNG, ...)
 * @param overrides position, altitude, heading, pitch, roll, field of view or focal length from the row
 * @param ranges    where the estimate searches, from the row ({@link SearchRanges#NONE}: nothing given)
 */
public record BatchPhoto(Path image, PhotoOverrides overrides, SearchRanges ranges) {
    public BatchPhoto {
        Objects.requireNonNull(image, "image");
        Objects.requireNonNull(overrides, "overrides");
        ranges = ranges == null ? SearchRanges.NONE : ranges;
    }
}
