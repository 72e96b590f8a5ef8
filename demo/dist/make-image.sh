#!/usr/bin/env bash
# Makes demo/target/openworld-linux/: a self-contained OpenWorld for Linux x64 that runs where no JDK is installed.
# Run by `./mvnw -B -Pdist -DskipTests package` after the jar is built; usage: make-image.sh JAR OUT_DIR.
#
#   bin/openworld     the launcher: this image's Java, its native libraries, the jar
#   runtime/          a Java runtime made by jlink with only the modules the jar needs (jdeps finds them)
#   lib/openworld.jar the jar with only the Linux x64 natives
#   lib/native/       the glvnd loader (libEGL.so.1, libGLdispatch.so.0): a GPU server's driver may come without it,
#                     and LWJGL's EGL loads it from here; and fontconfig and the font libraries the runtime's text
#                     drawing (bench's frametime.png) needs, which a bare server lacks
#   lib/fonts/        one font (DejaVu Sans) and the fontconfig file that names only it
#   legal/            the licences of everything above that is not OpenWorld's
# Built from this machine's JDK and libraries (Debian 12 here: glibc 2.36, so it runs on any newer glibc).
set -euo pipefail
jar=${1:?usage: make-image.sh JAR OUT_DIR}; out=${2:?usage: make-image.sh JAR OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
java_home=$(dirname "$(dirname "$(readlink -f "$(command -v javac || command -v java)")")")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
rm -rf "$out"; mkdir -p "$out/bin" "$out/lib/native" "$out/legal"

# 1. The jar, less the natives of other systems (Windows, macOS, Linux on ARM) and XChart's PDF and vector
#    back-ends (PDFBox, FontBox, VectorGraphics2D: only its PDF and SVG encoders use them; our charts are PNG).
#    Stored, not deflated: step 5's gzip packs the whole image tighter than zip packs each file.
mkdir "$work/classes"
(cd "$work/classes" && unzip -q "$jar" \
  && rm -rf windows macos linux/arm64 io/imgui/java/native-bin/*.dll io/imgui/java/native-bin/*.dylib \
     META-INF/versions/25 org/apache/pdfbox org/apache/fontbox org/apache/commons/logging de/rototor de/erichseifert \
  && zip -q -r -0 "$out/lib/openworld.jar" .)

# 2. The modules the classes use. The shaded jar carries LWJGL's module-info, which would make jdeps read the whole
#    jar as module org.lwjgl; without them it sees the classes as they are on the class path.
find "$work/classes" -name module-info.class -delete
found=$("$java_home/bin/jdeps" --multi-release 17 --ignore-missing-deps --print-module-deps "$work/classes")
# Left out of what jdeps finds: java.compiler (Error Prone's annotations, read only by compilers) and java.sql (Gson's
# optional date adapters, which Gson skips when the module is absent).
modules=$(tr , '\n' <<<"$found" | grep -vx 'java.compiler\|java.sql' | paste -sd, -)
echo "make-image: modules $modules (jdeps found $found)"

# 3. The runtime: those modules, no debug symbols, headers or manual pages; uncompressed for the same reason as the
#    jar, and faster to start.
"$java_home/bin/jlink" --add-modules "$modules" --output "$out/runtime" \
  --strip-debug --no-header-files --no-man-pages --compress=0
# java.desktop's natives for a screen, sound and a splash screen: a headless program never loads them.
rm -f "$out"/runtime/lib/{libawt_xawt,libjsound,libsplashscreen,libjawt}.so
strip --strip-unneeded "$out"/runtime/lib/server/libjvm.so # jlink's own stripping needs the symbols apart

# 4. Native libraries this machine's Java and EGL use that a bare GPU server has not.
libs=(libEGL.so.1 libGLdispatch.so.0 libfontconfig.so.1)
fontconfig=$(ldconfig -p | awk '$1 == "libfontconfig.so.1" && /x86-64/ && !found++ {print $NF}')
for lib in $(ldd "$out/runtime/lib/libfontmanager.so" ${fontconfig:+"$fontconfig"} | awk '/=>/ {print $1}' | sort -u); do
  case $lib in libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|libgcc_s.so*|libstdc++.so*|libz.so*|libjava.so|libjvm.so|libawt*) ;;
    *) libs+=("$lib");; esac
done
for lib in "${libs[@]}"; do
  path=$(ldconfig -p | awk -v l="$lib" '$1 == l && /x86-64/ && !found++ {print $NF}')
  [ -n "$path" ] || { echo "make-image: $lib not found (install it: libegl1 libfontconfig1)" >&2; exit 1; }
  cp -L "$path" "$out/lib/native/$lib"
  pkg=$(dpkg -S "$(readlink -f "$path")" 2>/dev/null | head -n 1 | cut -d: -f1) || true
  [ -n "$pkg" ] && [ -f "/usr/share/doc/$pkg/copyright" ] && cp "/usr/share/doc/$pkg/copyright" "$out/legal/$pkg.copyright"
done
font=$(fc-match -f '%{file}' 'DejaVu Sans:style=Book')
[ -f "$font" ] || { echo "make-image: the DejaVu Sans font not found (install fonts-dejavu-core)" >&2; exit 1; }
mkdir -p "$out/lib/fonts"; cp "$font" "$here/fonts.conf" "$out/lib/fonts/"
cp /usr/share/doc/fonts-dejavu-core/copyright "$out/legal/fonts-dejavu-core.copyright" 2>/dev/null || true
cp "$here/openworld" "$out/bin/openworld"; chmod +x "$out/bin/openworld"
size() { du -sm "$1" | cut -f1; }
echo "make-image: $out is $(size "$out") MiB: runtime $(size "$out/runtime"), jar $(size "$out/lib/openworld.jar"), native $(size "$out/lib/native"), fonts $(size "$out/lib/fonts")"
# 5. One file to carry: gzip (on every Linux) of the uncompressed runtime and a stored jar packs tighter than
#    jlink's and zip's own compression, which work one file at a time.
tar -C "$(dirname "$out")" -czf "$out.tar.gz" "$(basename "$out")"
echo "make-image: $out.tar.gz is $(size "$out.tar.gz") MiB"
