package dempano.camera;

/** What a compass direction is measured from: EXIF GPSImgDirectionRef. */
public enum DirectionReference {
    /** "T": true (geographic) north. */
    TRUE,
    /** "M": magnetic north; true = magnetic + declination (east positive), which the photo does not give. */
    MAGNETIC,
    /** No reference tag, or one other than T and M (and no direction at all). */
    NOT_GIVEN
}
