#version 330 core
#include "common/frame.glsl"
// Writes the frame block back out, one member per 8-pixel column, each scaled into 0..1 so an RGBA8 target keeps
// it to 1/255 (engine test: org.openworld.engine.gl.FrameUniformsTest, which knows the same scales).
uniform vec3 uProbePoint; // a world-space point the test also projects with JOML
out vec4 fragColor;

void main() {
    int column = int(gl_FragCoord.x) / 8;
    vec4 clip = frame.viewProjection * vec4(uProbePoint, 1.0);
    vec4 viaViewAndProjection = frame.projection * (frame.view * vec4(uProbePoint, 1.0));
    vec4 back = frame.invViewProjection * clip;
    float backError = length(back.xyz / back.w - uProbePoint);
    vec4 v;
    if (column == 0) {
        v = vec4(frame.viewport.xy / 256.0, frame.viewport.zw * 16.0);
    } else if (column == 1) {
        v = vec4(frame.cameraPosNear.xyz / 1000.0, frame.cameraPosNear.w);
    } else if (column == 2) {
        v = vec4(frame.sunDirFar.xyz * 0.5 + 0.5, frame.sunDirFar.w / 40000.0);
    } else if (column == 3) {
        v = vec4(frame.sunColor.rgb * 0.5, 1.0 - frame.sunColor.a);
    } else if (column == 4) {
        v = vec4(frame.ambientColor.rgb, 1.0 - frame.ambientColor.a);
    } else if (column == 5) {
        v = vec4(frame.exposure.x / 8.0, frame.exposure.yz, 1.0 - frame.exposure.w);
    } else if (column == 6) {
        v = vec4(frame.timeInfo.x * 5.0, frame.timeInfo.y / 24.0, frame.timeInfo.z / 8.0, 1.0 - frame.timeInfo.w);
    } else if (column == 7) {
        v = vec4(clip.xy / clip.w * 0.5 + 0.5, viaViewAndProjection.xy / viaViewAndProjection.w * 0.5 + 0.5);
    } else {
        v = vec4(clip.z / clip.w * 0.5 + 0.5, backError < 0.01 ? 1.0 : 0.0, 0.0, 1.0);
    }
    fragColor = v;
}
