package org.openworld.engine.bench;

import java.util.Map;

/**
 * What a benchmark run was: the machine's renderer and the exact inputs, so two runs can be compared honestly.
 *
 * @param renderer  GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
 * @param glVersion GL_VERSION
 * @param contextMode window, headless-egl or headless-x11
 * @param width     render width, pixels
 * @param height    render height, pixels
 * @param seed      world seed
 * @param settings  every setting key with its value as text
 * @param path      the camera path file replayed
 * @param warmup    frames rendered before recording
 * @param profiled  whether the GPU was finished around every span ({@code bench --profile})
 */
public record RunInfo(String renderer, String glVersion, String contextMode, int width, int height, long seed,
                      Map<String, String> settings, String path, int warmup,
                      boolean profiled) {
}
