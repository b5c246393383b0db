package dempano.util;

import java.util.regex.Pattern;

/**
 * Plain decimal numbers as the project reads them from users (flags, CSV cells, summit lists, XMP): an optional
 * sign, digits with an optional point, an optional exponent. Not NaN, Infinity, hexadecimal ({@code 0x1p5}), type
 * suffixes ({@code 46d}, {@code 43.8f}), digit separators or decimal commas, all of which {@link Double#parseDouble}
 * would take or misread. Stateless.
 */
public final class Decimals {
    private static final Pattern PLAIN = Pattern.compile("[+-]?(?:\\d+(?:\\.\\d*)?|\\.\\d+)(?:[eE][+-]?\\d+)?");

    private Decimals() {
    }

    /** Whether {@code text} (not trimmed) is a plain decimal number; it may still overflow to ±∞ when parsed. */
    public static boolean isPlain(String text) {
        return text != null && PLAIN.matcher(text).matches();
    }
}
