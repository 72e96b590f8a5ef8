package org.openworld.engine.shadow;

import java.util.Arrays;
import org.joml.Matrix4f;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.joml.Vector4f;
import org.openworld.engine.shadow.ShadowSettings.Refresh;

/**
 * Which cascades are redrawn this frame, and which keep the depths (and the box) they were last drawn with. GL-free.
 *
 * <p>A map holds the casters' depths as seen through one box. While the newly fitted box is the very same (the stable
 * fit moves a box by whole texels only, so a box stands still until the camera has moved a texel's worth) and the
 * casters are unchanged (no setting changed), redrawing it would write the same depths: it is kept. The sun turning
 * turns every box, by a fraction of a texel a frame; a map is kept, with its box fitted to the old direction, until
 * the sun has turned by more than the refresh angle. With {@link Refresh#STAGGERED}, a far cascade whose box moved is
 * redrawn only on its own frames: cascade i on frames whose count has exactly i − 1 trailing zero bits (1 on odd
 * frames, 2 on frames 2, 6, 10, ..., 3 on 4, 12, 20, ...), so it waits at most 2^i frames and the far cascades never
 * share a frame. Until then it keeps its old box, consistent with its depths, as long as that box still holds every
 * corner of its slice of the view; one that no longer does is redrawn at once.
 */
final class CascadeRefresh {

    /** One map as last drawn: its box and the sun it was fitted to. */
    private record Kept(LightBox box, Vector3fc toSun) {
    }

    private Kept[] kept = new Kept[0];
    private long frame;

    /** Forgets every map (new maps, other settings, the sun set): each is redrawn when next asked about. */
    void forget(int maps) {
        kept = new Kept[maps];
    }

    /** Counts a frame: the stagger's clock. */
    void nextFrame() {
        frame++;
    }

    /**
     * The sun to fit map {@code i} to: the one its kept map was drawn for, while the sun has turned from that by at
     * most {@code angleDegrees}; else today's.
     */
    Vector3fc sunFor(int i, Vector3fc toSun, double angleDegrees, Refresh refresh) {
        Kept k = kept[i];
        if (refresh == Refresh.ALWAYS || k == null) {
            return toSun;
        }
        return k.toSun().angle(toSun) <= Math.toRadians(angleDegrees) ? k.toSun() : toSun;
    }

    /**
     * Whether map {@code i} is redrawn with the {@code fitted} box this frame; if so it is remembered as drawn.
     *
     * @param fitted  this frame's box, fitted to {@link #sunFor}'s sun
     * @param toSun   the sun it was fitted to
     * @param corners the 8 world corners of the map's slice of the view
     */
    boolean redraw(int i, LightBox fitted, Vector3fc toSun, Vector3d[] corners, Refresh refresh) {
        Kept k = kept[i];
        boolean redraw = switch (refresh) {
            case ALWAYS -> true;
            case MOVED -> k == null || !k.box().equals(fitted);
            case STAGGERED -> k == null || !k.box().equals(fitted) && (mayRedraw(i, frame) || !holds(k.box(), corners));
        };
        if (redraw) {
            kept[i] = new Kept(fitted, new Vector3f(toSun));
        }
        return redraw;
    }

    /** The box map {@code i} holds its depths for: the one drawn last (after {@link #redraw}: this frame's, or kept). */
    LightBox box(int i) {
        return kept[i].box();
    }

    /** Whether the stagger lets cascade {@code i} be redrawn on frame {@code frame}: 0 always, i on its own frames. */
    static boolean mayRedraw(int i, long frame) {
        return i == 0 || Long.numberOfTrailingZeros(frame) == i - 1;
    }

    /** Whether every corner lies inside the box (its clip space, −1 .. 1 in x, y and depth). */
    static boolean holds(LightBox box, Vector3d[] corners) {
        Matrix4f toClip = box.viewProjection();
        Vector4f clip = new Vector4f();
        return Arrays.stream(corners).allMatch(c -> {
            toClip.transform((float) c.x, (float) c.y, (float) c.z, 1, clip);
            return Math.abs(clip.x) <= 1 && Math.abs(clip.y) <= 1 && Math.abs(clip.z) <= 1;
        });
    }
}
