/**
 * The realistic camera of the paper's section 1. One system, the director
 * ({@link org.openworld.engine.camera.CameraSystem}), writes the camera's pose at the start of every update, as the
 * world's {@link org.openworld.engine.camera.CameraDirection} says: the user's controls, which fly with inertia or
 * walk on the ground ({@link org.openworld.engine.camera.CameraController}, its motion model and formulas in the
 * class comment), a scripted camera path that replays identically for benchmarks, or a fixed pose for pictures.
 *
 * <p><b>Paths.</b> A plain-text file of keyframes {@code time x y z yaw pitch [fov]}
 * ({@link org.openworld.engine.camera.CameraPathParser}, errors as {@code file:line:column: expected …, found …}).
 * Position follows a centripetal Catmull-Rom spline ({@link org.openworld.engine.camera.CatmullRom}: knot spacing
 * {@code |P_{i+1} − P_i|^0.5}, which rules out cusps and self-intersections within a segment); yaw is unwrapped so
 * consecutive keys differ by at most 180° and, with pitch and fov, follows a monotone cubic
 * ({@link org.openworld.engine.camera.MonotoneCubic}) that never overshoots a key. The window records paths with R
 * ({@link org.openworld.engine.camera.CameraPathRecorder}, a key every 0.25 s).
 *
 * <p><b>Cost.</b> Constant per update and per sample (a binary search over keys). <b>Limits.</b> Speed along a path
 * is continuous within a segment but may change at a key when neighbouring segments differ in length per second;
 * see {@code docs/camera-paths.md}.
 */
package org.openworld.engine.camera;
