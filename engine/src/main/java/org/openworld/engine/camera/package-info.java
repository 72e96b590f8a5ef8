/**
 * The realistic camera of the paper's section 1: a controller that flies with inertia or walks on the ground
 * ({@link org.openworld.engine.camera.CameraSystem}, its motion model and formulas in the class comment), and
 * scripted camera paths that replay identically for benchmarks and figures.
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
