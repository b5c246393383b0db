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

    /**
     * A number for messages as people write it: at most {@code significantDigits} significant digits, no exponent, no
     * trailing zeros (400, 0.1, 42949672.95, 80000000); NaN and ±∞ as Java writes them.
     */
    public static String shortest(double v, int significantDigits) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        return java.math.BigDecimal.valueOf(v).round(new java.math.MathContext(significantDigits)).stripTrailingZeros()
                .toPlainString();
    }

    /** Whether {@code text} (not trimmed) is a plain decimal number; it may still overflow to ±∞ when parsed. */
    public static boolean isPlain(String text) {
        return text != null && PLAIN.matcher(text).matches();
    }
}
