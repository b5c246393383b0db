import java.awt.image.BufferedImage;
import java.io.*;
import java.util.*;
import javax.imageio.*;
import javax.imageio.stream.*;

/** PNG deflate settings against time and size on one colour image: java scripts/PngLevels.java P.png (docs/cold-start.md). */
public class PngLevels {
    public static void main(String[] a) throws Exception {
        BufferedImage img = ImageIO.read(new File(a[0]));
        BufferedImage argb = new BufferedImage(img.getWidth(), img.getHeight(), BufferedImage.TYPE_INT_RGB);
        argb.getGraphics().drawImage(img, 0, 0, null);
        System.out.println("type " + img.getType() + " " + img.getWidth() + "x" + img.getHeight());
        for (int rep = 0; rep < 4; rep++) {
            for (String mode : new String[] {"default", "q0.5", "q0.75", "q0.9"}) {
                ByteArrayOutputStream bos = new ByteArrayOutputStream();
                long t = System.nanoTime();
                if (mode.equals("default")) {
                    ImageIO.write(argb, "png", bos);
                } else {
                    ImageWriter w = ImageIO.getImageWritersByFormatName("png").next();
                    ImageWriteParam p = w.getDefaultWriteParam();
                    p.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
                    p.setCompressionQuality(Float.parseFloat(mode.substring(1)));
                    try (ImageOutputStream ios = ImageIO.createImageOutputStream(bos)) {
                        w.setOutput(ios);
                        w.write(null, new IIOImage(argb, null, null), p);
                    }
                    w.dispose();
                }
                long ms = (System.nanoTime() - t) / 1_000_000;
                BufferedImage back = ImageIO.read(new ByteArrayInputStream(bos.toByteArray()));
                boolean same = true;
                for (int y = 0; y < argb.getHeight() && same; y++) for (int x = 0; x < argb.getWidth(); x++) if (argb.getRGB(x, y) != back.getRGB(x, y)) { same = false; break; }
                System.out.println(rep + " " + mode + " " + ms + " ms " + bos.size() + " bytes same=" + same);
            }
        }
    }
}
