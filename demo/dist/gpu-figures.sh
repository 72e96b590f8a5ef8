#!/usr/bin/env bash
# The GPU figures in one go, on a bare GPU server (a driver, no Java, no X): run from the repository root with the
# runtime image (-Pdist) and the peer kit (gpu-kit.sh) carried beside it; everything is written to OUT_DIR.
#
#   demo/dist/gpu-figures.sh OUT_DIR
#
# Environment: IMAGE (default demo/target/openworld-linux.tar.gz; the image's folder works too), KIT (default
# demo/target/gpu-kit), QUICK=1 (tiny sizes and a few frames: checks the script end to end on any machine, llvmpipe
# included), DEADLINE (seconds for the whole run, default 280: a step that would start later is skipped).
#
# Steps, each under its own timeout and each recorded in OUT_DIR/steps.tsv (name, exit code, seconds) whatever the
# others did: the machine (nvidia-smi, uname); openworld info; the default shot at 1920x1080; bench on
# assets/paths/crossing.path at 1920x1080 and 3840x2160 with the default, ultra and low presets; the default crossing
# at 1920x1080 again with the vegetation off, the anti-aliasing off and the volumetric clouds on; bench on the peer's
# four views (its imported map and camera circle, set as ../shared/peer/compare.sh sets them: terrain, shadows, water,
# all) at 1920x1080. Each bench folder has summary.json: the GPU time per pass and system (timer queries,
# passGpuMsMedian), the CPU time per system (systemCpuMsMedian), frame times, triangles and draw calls; at the end
# OUT_DIR/figures.tsv has one line per bench (demo/dist/gpu-table.py --tsv, where the machine has python3). Unless
# QUICK=1, the run stops after info when info names no renderer or a software one (llvmpipe): no GPU, no figures.
set -uo pipefail
out=${1:?usage: gpu-figures.sh OUT_DIR}
image=${IMAGE:-demo/target/openworld-linux.tar.gz}
kit=${KIT:-demo/target/gpu-kit}
deadline=${DEADLINE:-280}
mkdir -p "$out"
out=$(cd "$out" && pwd)
kit=$(cd "$kit" 2>/dev/null && pwd) || echo "gpu-figures: no kit at ${KIT:-demo/target/gpu-kit}: the peer views will fail" >&2
start=$SECONDS

if [ "${QUICK:-0}" = 1 ]; then
  hd=160x90; uhd=192x108; frames=3; peer_frames=3; warmup=1; bench_s=120; shot_s=90
else
  hd=1920x1080; uhd=3840x2160; frames=600; peer_frames=300; warmup=60; bench_s=75; shot_s=60
fi

# The image: unpacked next to nothing we bring back.
if [ -d "$image" ]; then
  home=$image
else
  unpacked=$(mktemp -d); trap 'rm -rf "$unpacked"' EXIT
  tar -C "$unpacked" -xzf "$image" || { echo "gpu-figures: cannot unpack $image" >&2; exit 1; }
  home=$unpacked/openworld-linux
fi
openworld=$home/bin/openworld

printf 'step\texit\tseconds\n' >"$out/steps.tsv"
# step NAME TIMEOUT_S COMMAND...: runs it with stdout and stderr in OUT/NAME.log, carries on whatever happens.
step() {
  local name=$1 limit=$2; shift 2
  local left=$((deadline - (SECONDS - start)))
  if [ "$left" -le 5 ]; then
    printf '%s\tskipped\t0\n' "$name" >>"$out/steps.tsv"; echo "gpu-figures: $name skipped (deadline)"; return
  fi
  [ "$limit" -gt "$left" ] && limit=$left
  local t0=$SECONDS
  timeout --kill-after=10 "$limit" "$@" >"$out/$name.log" 2>&1
  local rc=$?
  printf '%s\t%s\t%s\n' "$name" "$rc" "$((SECONDS - t0))" >>"$out/steps.tsv"
  echo "gpu-figures: $name exit $rc in $((SECONDS - t0)) s"
}

# NVIDIA's container layout keeps the driver's libraries here, not always in the loader's cache.
[ -d /usr/local/nvidia/lib64 ] && export LD_LIBRARY_PATH=${LD_LIBRARY_PATH:+$LD_LIBRARY_PATH:}/usr/local/nvidia/lib64

# 1. The machine and what every headless mode says on it (again with LWJGL's own report when that fails).
{ date -u; uname -a; nvidia-smi 2>&1; ls /usr/share/glvnd/egl_vendor.d 2>&1; ldconfig -p 2>&1 | grep -i "egl\|nvidia"
  nproc; free -m 2>&1; } >"$out/machine.txt"
step info 60 "$openworld" info
if ! grep -q "^renderer:" "$out/info.log"; then
  JAVA_OPTS="-Dorg.lwjgl.util.Debug=true -Dorg.lwjgl.util.DebugLoader=true" step info-debug 60 "$openworld" info
fi

if [ "${QUICK:-0}" != 1 ]; then
  renderer=$(grep -h "^renderer:" "$out/info.log" "$out/info-debug.log" 2>/dev/null | head -1)
  if [ -z "$renderer" ] || grep -qiE "llvmpipe|softpipe|swrast|software" <<<"$renderer"; then
    echo "gpu-figures: stopping after info: ${renderer:-no renderer} is not a GPU (see $out/info.log)" >&2
    exit 1
  fi
fi

# 2. The default shot.
step shot "$shot_s" "$openworld" shot --out "$out/shot-$hd.png" --size "$hd"

# 3. The crossing at two sizes and three presets.
for size in "$hd" "$uhd"; do
  for preset in default ultra low; do
    step "bench-crossing-$preset-$size" "$bench_s" "$openworld" bench --path assets/paths/crossing.path \
      --preset "$preset" --size "$size" --frames "$frames" --warmup "$warmup" --out "$out/bench-crossing-$preset-$size"
  done
done

# 4. What this release's features cost on the crossing at 1920x1080, default preset: each one switched off (or, for
#    the volumetric clouds, on) against the default bench of step 3.
for feature in vegetation=system.vegetation=off antialias=antialias.method=off clouds=clouds.mode=volumetric; do
  step "bench-crossing-${feature%%=*}-$hd" "$bench_s" "$openworld" bench --path assets/paths/crossing.path \
    --size "$hd" --frames "$frames" --warmup "$warmup" --set "${feature#*=}" \
    --out "$out/bench-crossing-${feature%%=*}-$hd"
done

# 5. The peer's four views: its map and circle, with what the peer has no counterpart for switched off (as
#    ../shared/peer/compare.sh does: a key this build lacks is left out).
known=$("$openworld" settings 2>/dev/null | awk '{print $1}')
same=(--set terrain.spacing=1 --set terrain.relief=150 --set terrain.import-file="$kit/heightmap-1025.f32")
for k in system.trees system.vegetation system.grass; do grep -qx "$k" <<<"$known" && same+=(--set "$k=off"); done
grep -qx clouds.mode <<<"$known" && same+=(--set clouds.mode=layer)
grep -qx terrain.erosion <<<"$known" && same+=(--set terrain.erosion=off)
cascades=(--set shadow.cascades=3 --set shadow.resolution=2048 --set shadow.distance=2000)
for view in terrain shadows water all; do
  case $view in
    terrain) sea=0; circle=dry; set_view=(--set system.shadow=off --set system.water=off);;
    shadows) sea=0; circle=dry; set_view=(--set system.water=off "${cascades[@]}");;
    water)   sea=0.35; circle=sea; set_view=(--set system.shadow=off);;
    all)     sea=0.35; circle=sea; set_view=("${cascades[@]}");;
  esac
  step "bench-peer-$view-$hd" "$bench_s" "$openworld" bench --path "$kit/circle-$circle.path" --size "$hd" \
    --frames "$peer_frames" --warmup "$warmup" --time 09:00 --out "$out/bench-peer-$view-$hd" \
    "${same[@]}" --set terrain.sea-fraction="$sea" "${set_view[@]}"
done

# 6. The figures at a glance, one line per bench.
here=$(dirname "$0")
if command -v python3 >/dev/null; then
  python3 "$here/gpu-table.py" --tsv "$out" >"$out/figures.tsv" || echo "gpu-figures: no figures.tsv" >&2
fi

echo "gpu-figures: done in $((SECONDS - start)) s; steps in $out/steps.tsv"
