package org.openworld.demo;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.GradientPaint;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.geom.Arc2D;
import java.awt.geom.Area;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import javax.imageio.ImageIO;
import org.openworld.engine.files.AtomicFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld diagram}: the paper's figure 7, "Illustration of the scattering equations", drawn with Java2D:
 * the eye a on the ground, the planet's curve and the atmosphere's shell, the view ray from a to where it leaves the
 * atmosphere at b with the outer sum's points p at the midpoints of equal steps, and from each p the inner ray
 * toward the sun to the top of the atmosphere at c with the inner sum's points. The sums are those of
 * {@code SkyIntegrator} in single scattering ({@code atmosphere.outer-samples}, {@code atmosphere.inner-samples});
 * the shell is drawn about 10 times thicker than Earth's (100 km on 6360) so it can be seen.
 */
@Command(name = "diagram", mixinStandardHelpOptions = true,
        description = "Draw the paper's figure 7, the scattering sums: the eye, the view ray's outer samples, the "
                + "inner rays to the sun and the atmosphere's shell.")
final class DiagramCommand implements Callable<Integer> {

    @Mixin
    DevOption dev;

    private static final int WIDTH = 1200;
    private static final int HEIGHT = 760;
    /** The planet's centre and radii, pixels: a gentle curve across the picture. */
    private static final double CENTRE_X = 560;
    private static final double CENTRE_Y = 3120;
    /** The scene above, the legend below this line, pixels. */
    private static final int LEGEND_TOP = 650;
    private static final double GROUND_RADIUS = 2560;
    private static final double TOP_RADIUS = 2950;
    /** The view ray's and the sun's elevations at the eye, degrees. */
    private static final double VIEW_ELEVATION = 14;
    private static final double SUN_ELEVATION = 62;
    private static final int OUTER_SAMPLES = 4;
    private static final int INNER_SAMPLES = 3;

    private static final Color INK = new Color(0x22, 0x22, 0x22);
    private static final Color VIEW = new Color(0x1f, 0x5f, 0xbf);
    private static final Color SUN = new Color(0xd0, 0x80, 0x00);
    private static final Color GROUND = new Color(0x8a, 0x9a, 0x6a);
    private static final Font LABEL = new Font(Font.SANS_SERIF, Font.PLAIN, 20);
    private static final Font NAME = new Font(Font.SANS_SERIF, Font.BOLD | Font.ITALIC, 24);
    private static final Font SMALL = new Font(Font.SANS_SERIF, Font.PLAIN, 16);

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "The diagram, a PNG file.")
    Path out;

    @Override
    public Integer call() throws Exception {
        Outputs.png(out, false);
        BufferedImage image = draw();
        AtomicFiles.write(out, file -> ImageIO.write(image, "png", file.toFile()));
        System.out.println("diagram: figure 7 written to " + out);
        return 0;
    }

    static BufferedImage draw() {
        BufferedImage image = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, WIDTH, HEIGHT);

        // the atmosphere: the shell between the ground and the top, bluer near the ground where the air is dense
        Area shell = new Area(circle(TOP_RADIUS));
        shell.subtract(new Area(circle(GROUND_RADIUS)));
        double groundTop = CENTRE_Y - GROUND_RADIUS;
        double airTop = CENTRE_Y - TOP_RADIUS;
        g.setPaint(new GradientPaint(0, (float) airTop, new Color(0xf4, 0xf8, 0xff), 0, (float) groundTop,
                new Color(0xb8, 0xd4, 0xf4)));
        g.fill(shell);
        g.setClip(0, 0, WIDTH, LEGEND_TOP);
        g.setColor(GROUND);
        g.fill(circle(GROUND_RADIUS));
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {8, 6}, 0));
        g.setColor(new Color(0x50, 0x70, 0xa0));
        g.draw(circle(TOP_RADIUS));

        // the eye a, the view ray a -> b, and the sun's direction
        Point2D.Double a = new Point2D.Double(150, ground(150));
        double[] normal = unit(a.x - CENTRE_X, a.y - CENTRE_Y);
        double[] view = rotate(normal, 90 - VIEW_ELEVATION);
        double[] sun = rotate(normal, 90 - SUN_ELEVATION);
        Point2D.Double b = along(a, view, exit(a, view, TOP_RADIUS));

        // the inner rays first, so the view ray is drawn over them
        double length = a.distance(b);
        double step = length / OUTER_SAMPLES;
        Point2D.Double[] p = new Point2D.Double[OUTER_SAMPLES];
        Point2D.Double[] c = new Point2D.Double[OUTER_SAMPLES];
        for (int i = 0; i < OUTER_SAMPLES; i++) {
            p[i] = along(a, view, (i + 0.5) * step);
            double toTop = exit(p[i], sun, TOP_RADIUS);
            c[i] = along(p[i], sun, toTop);
            g.setColor(SUN);
            g.setStroke(new BasicStroke(2.2f));
            arrow(g, p[i], c[i]);
            for (int k = 0; k < INNER_SAMPLES; k++) {
                dot(g, along(p[i], sun, (k + 0.5) * toTop / INNER_SAMPLES), 5, SUN, false);
            }
            // the light goes on toward the sun outside the atmosphere, faintly
            g.setStroke(new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {4, 5},
                    0));
            g.draw(new Line2D.Double(c[i], along(c[i], sun, 60)));
        }

        // the view ray, its steps and the outer sum's points
        g.setColor(VIEW);
        g.setStroke(new BasicStroke(3f));
        arrow(g, a, b);
        for (int i = 1; i < OUTER_SAMPLES; i++) {
            tick(g, along(a, view, i * step), view, 9);
        }
        for (int i = 0; i < OUTER_SAMPLES; i++) {
            dot(g, p[i], 7, VIEW, true);
        }
        dot(g, a, 8, INK, true);
        dot(g, b, 6, INK, true);

        // one point p in detail: its height h, its angle θ, t(a, p) and t(p, c)
        int shown = 2;
        Point2D.Double ps = p[shown];
        double[] up = unit(ps.x - CENTRE_X, ps.y - CENTRE_Y);
        double hLength = ps.distance(CENTRE_X, CENTRE_Y) - GROUND_RADIUS;
        Point2D.Double foot = along(ps, up, -hLength);
        g.setColor(INK);
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {5, 4}, 0));
        g.draw(new Line2D.Double(ps, foot));
        g.setFont(LABEL);
        text(g, "h", midpoint(ps, foot), 10, 6);
        g.setStroke(new BasicStroke(1.5f));
        double viewAngle = Math.toDegrees(Math.atan2(-view[1], view[0]));
        double sunAngle = Math.toDegrees(Math.atan2(-sun[1], sun[0]));
        double radius = 46;
        g.draw(new Arc2D.Double(ps.x - radius, ps.y - radius, 2 * radius, 2 * radius, viewAngle,
                sunAngle - viewAngle, Arc2D.OPEN));
        Point2D.Double thetaAt = along(ps, rotate(view, -(sunAngle - viewAngle) / 2), radius + 16);
        text(g, "θ", thetaAt, -6, 7);

        g.setFont(NAME);
        g.setColor(INK);
        text(g, "a", a, -32, -6);
        text(g, "b", b, 10, -8);
        text(g, "p", ps, 8, 28);
        text(g, "c", c[shown], 10, -6);
        g.setFont(LABEL);
        g.setColor(VIEW);
        text(g, "t(a, p)", midpoint(a, ps), -20, 34);
        g.setColor(SUN);
        text(g, "t(p, c)", midpoint(ps, c[shown]), 12, 0);

        // the sun, far away in the sun's direction
        Point2D.Double sunAt = along(c[OUTER_SAMPLES - 1], sun, 120);
        sunAt = new Point2D.Double(Math.min(sunAt.x, WIDTH - 70), Math.max(sunAt.y, 70));
        g.setColor(SUN);
        g.fill(new Ellipse2D.Double(sunAt.x - 26, sunAt.y - 26, 52, 52));
        g.setStroke(new BasicStroke(2.5f));
        for (int r = 0; r < 12; r++) {
            double[] d = rotate(new double[] {1, 0}, r * 30);
            g.draw(new Line2D.Double(sunAt.x + 34 * d[0], sunAt.y + 34 * d[1], sunAt.x + 46 * d[0],
                    sunAt.y + 46 * d[1]));
        }
        g.setFont(LABEL);
        text(g, "sun", sunAt, -96, 8);

        // names of the parts and the sums
        g.setFont(LABEL);
        g.setColor(new Color(0x50, 0x70, 0xa0));
        text(g, "top of the atmosphere", new Point2D.Double(24, top(24)), 0, 28);
        g.setColor(Color.WHITE);
        text(g, "ground: the planet's curve", new Point2D.Double(WIDTH - 330, ground(WIDTH - 330)), 0, 32);
        text(g, "eye", a, -20, 30);
        g.setClip(null);

        g.setFont(SMALL);
        g.setColor(INK);
        String[] legend = {
            "Outer sum (filled): the view ray from the eye a to b, at the top, in equal steps, a point p "
                    + "in the middle of each (atmosphere.outer-samples).",
            "Inner sum (hollow): from each p toward the sun to the top at c, in equal steps "
                    + "(atmosphere.inner-samples): the optical depth t(p, c).",
            "I(λ) = F(θ) S(λ) K(λ) Σ_p exp(−h/H₀) exp(−(t(a, p) + t(p, c))) Δs        "
                    + "t(a, b, λ) = K(λ) Σ exp(−h/H₀) Δs        (equations 4 and 3)",
        };
        for (int i = 0; i < legend.length; i++) {
            g.drawString(legend[i], 24, LEGEND_TOP + 34 + 28 * i);
        }
        g.dispose();
        return image;
    }

    private static Shape circle(double radius) {
        return new Ellipse2D.Double(CENTRE_X - radius, CENTRE_Y - radius, 2 * radius, 2 * radius);
    }

    private static double ground(double x) {
        return CENTRE_Y - Math.sqrt(GROUND_RADIUS * GROUND_RADIUS - (x - CENTRE_X) * (x - CENTRE_X));
    }

    private static double top(double x) {
        return CENTRE_Y - Math.sqrt(TOP_RADIUS * TOP_RADIUS - (x - CENTRE_X) * (x - CENTRE_X));
    }

    /** Distance from {@code from} along the unit direction {@code d} to the circle of {@code radius}, from inside. */
    private static double exit(Point2D.Double from, double[] d, double radius) {
        double ox = from.x - CENTRE_X;
        double oy = from.y - CENTRE_Y;
        double half = ox * d[0] + oy * d[1];
        return -half + Math.sqrt(half * half - (ox * ox + oy * oy - radius * radius));
    }

    private static Point2D.Double along(Point2D.Double from, double[] d, double distance) {
        return new Point2D.Double(from.x + d[0] * distance, from.y + d[1] * distance);
    }

    private static Point2D.Double midpoint(Point2D.Double first, Point2D.Double second) {
        return new Point2D.Double((first.x + second.x) / 2, (first.y + second.y) / 2);
    }

    private static double[] unit(double x, double y) {
        double length = Math.hypot(x, y);
        return new double[] {x / length, y / length};
    }

    /** {@code d} turned clockwise on the screen (toward +x from up) by {@code degrees}. */
    private static double[] rotate(double[] d, double degrees) {
        double r = Math.toRadians(degrees);
        return new double[] {d[0] * Math.cos(r) - d[1] * Math.sin(r), d[0] * Math.sin(r) + d[1] * Math.cos(r)};
    }

    private static void arrow(Graphics2D g, Point2D.Double from, Point2D.Double to) {
        g.draw(new Line2D.Double(from, to));
        double[] d = unit(to.x - from.x, to.y - from.y);
        double[] left = rotate(d, 155);
        double[] right = rotate(d, -155);
        Path2D.Double head = new Path2D.Double();
        head.moveTo(to.x, to.y);
        head.lineTo(to.x + 14 * left[0], to.y + 14 * left[1]);
        head.lineTo(to.x + 14 * right[0], to.y + 14 * right[1]);
        head.closePath();
        g.fill(head);
    }

    private static void tick(Graphics2D g, Point2D.Double at, double[] along, double half) {
        double[] across = rotate(along, 90);
        g.draw(new Line2D.Double(at.x - half * across[0], at.y - half * across[1], at.x + half * across[0],
                at.y + half * across[1]));
    }

    private static void dot(Graphics2D g, Point2D.Double at, double radius, Color colour, boolean filled) {
        Ellipse2D.Double disc = new Ellipse2D.Double(at.x - radius, at.y - radius, 2 * radius, 2 * radius);
        g.setColor(filled ? colour : Color.WHITE);
        g.fill(disc);
        g.setColor(colour);
        g.setStroke(new BasicStroke(2f));
        g.draw(disc);
    }

    private static void text(Graphics2D g, String text, Point2D.Double at, double dx, double dy) {
        g.drawString(text, (float) (at.x + dx), (float) (at.y + dy));
    }
}
