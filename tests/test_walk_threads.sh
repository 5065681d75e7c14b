#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The threaded walk end to end (firmware/walk/sw_seam_walk.h, "Threads"):
#   test_walk_threads.sh BUILD_DIR SOURCE_DIR
# - P never blocks on T: the workers stalled from frame 4 on (a test hook),
#   every frame still comes, drawn from the meshes it has, crack-free (0
#   cracks, 0 gaps in the seams as drawn), the work left undone counted as
#   frames behind; were the GL thread waiting for a worker the walk would
#   hang and the test time out (ctest TIMEOUT);
# - the async walk with two workers on its own: crack-free every measured
#   frame, no allocation after init, batches swapped in, jobs stolen;
# - slow workers (each job published 15 ms late, a test hook): batches take
#   many frames, and none may show before it is whole: no T-vertex, gap or
#   crack. Limit: a walk deliberately broken to swap each mesh in as it
#   came (not whole batches) passed this too, on the teaset, a 2,000- and
#   the 40,000-patch showroom: the seams as drawn did not tell the two
#   apart there, so the batch rule rests on its construction
#   (firmware/walk/sw_seam_walk.h) more than on this check.
# - the visibility thread V (firmware/walk/sw_seam_visibility.h): with workers
#   every frame's plan is made off the GL thread, and V plans frame i+1
#   while P draws frame i (overlapped frames > 0: V began planning before
#   P had finished the frame before); --visibility-thread 0 plans on the GL
#   thread, and --sync-work 1 runs the two in lockstep (no overlap);
# - --sync-work 1 (the tests' deterministic frames) draws exactly what
#   --workers 0 draws, with V on its thread and without;
# - bad --workers / --target-ms values and too little memory for the
#   workers are one clear error line.
# Every walk here passes --sync-work 0 itself: the suite sets
# SEAMWALK_TEST_SYNC_WORK=1 for everything else.
set -uo pipefail
build=$1 src=$2
work=$build/tests/walk_threads
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
walker=$build/firmware/seamwalk
"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" \
  > /dev/null || fail "build"
# The surfaces' walk, which the threads run: the orbit of a teaset at
# 320x240 is far enough for the part levels to draw it whole.
walk() { "$walker" --pack "$work/teaset.swpack" --headless 320x240 --orbit --part-levels 0 "$@"; }

# The stalled walk without static levels: its first frame is then made
# coarser and waited for, and those meshes are what it draws behind (with
# levels, stand-ins would draw them, which tests/test_standins.sh checks).
walk --frames 24 --measure-every 1 --workers 1 --sync-work 0 --test-stall-workers 4 \
  --static-levels 0 --stats "$work/stalled.json" > /dev/null || fail "walk with the workers stalled"
walk --frames 24 --measure-every 1 --workers 2 --sync-work 0 --stats "$work/async.json" \
  > /dev/null || fail "walk with two workers"
walk --frames 24 --measure-every 1 --workers 1 --sync-work 0 --test-slow-workers 15 \
  --stats "$work/slow.json" > /dev/null || fail "walk with slow workers"
python3 - "$work/stalled.json" "$work/async.json" "$work/slow.json" <<'PY' || fail "threaded walks"
import json, sys
stalled, run, slow = (json.load(open(p)) for p in sys.argv[1:4])
for name, j in (("stalled", stalled), ("async", run), ("slow", slow)):
    t = j["threads"]
    print("  %s: %d frames, tris median %d, cracks %d, gaps %d, T-vertices %d, batches %d, "
          "jobs %d, frames behind max %d, bound ratio max %.2f, steals %d, error max %.3f px"
          % (name, j["frames"], j["tris_per_frame"]["median"], j["cracks_max"],
             j["seam_drawn"]["gaps_max"], j["seam_drawn"]["t_vertices_max"], t["batches"], t["jobs"], t["frames_behind_max"],
             t["behind_ratio_max"], t["steals"], j["error_px"]["max"]))
    assert j["frames"] == 24, name
    assert j["cracks_max"] == 0 and j["seam_drawn"]["gaps_max"] == 0, name
    assert j["seam_drawn"]["t_vertices_max"] == 0, name
    assert j["seam_drawn"]["unchecked_frames"] == 0, name
    assert j["mallocs_after_init"] == 0, name
    assert t["sync_work"] == 0 and t["workers"] >= 1, name
    assert j["tris_per_frame"]["median"] > 0, name
# Stalled from frame 4: the batches that came before are all it swapped
# in; what it asked for after waits, and the stats say how long.
assert stalled["threads"]["batches"] <= 6
assert stalled["threads"]["frames_behind_max"] >= 10
# Meshes drawn coarser than asked are measured apart: the stalled walk has
# them (its first frame's meshes, made at SW_SEAM_FIRST_COARSER times the
# bound, are never replaced), and error_px keeps within the bound what was made for it.
assert stalled["error_px_behind"]["samples"] > 0, stalled["error_px_behind"]
assert stalled["threads"]["behind_ratio_max"] > 1
beyond = stalled["seam"]["error_px_beyond_sewing_max"]
assert beyond <= stalled["error_px"]["bound"], beyond
# V on its own thread, overlapping P's frames (frame 0 has nothing before it).
for name, j in (("stalled", stalled), ("async", run), ("slow", slow)):
    v = j["visibility"]
    assert v["thread"] and v["planned_on_gl_thread"] == 0, (name, v)
    assert 0 < v["overlapped_frames"] <= 23, (name, v)
# The async walk keeps swapping work in. Not "fewer frames behind than the
# stalled walk": that is one surface's worst, and under TSan on a loaded
# machine (frames of 100 ms and more, so small budgets) a surface the async
# walk kept passing over was 20 frames behind against the stalled walk's 19.
# Nor "more triangles made than the stalled walk": that walk has no static
# levels, so its workers mesh every surface for its first frame, where the
# async walk draws stand-ins and its workers refine only what is close.
assert run["threads"]["batches"] > stalled["threads"]["batches"]
assert run["threads"]["worker_triangles"] > 0
PY

walk --frames 6 --workers 1 --sync-work 0 --visibility-thread 0 --stats "$work/on_gl.json" \
  > /dev/null || fail "walk with --visibility-thread 0"
python3 - "$work/on_gl.json" <<'PY' || fail "--visibility-thread 0"
import json, sys
v = json.load(open(sys.argv[1]))["visibility"]
assert not v["thread"] and v["planned_on_gl_thread"] == 6 and v["overlapped_frames"] == 0, v
PY

modes=("--workers 0" "--workers 1 --sync-work 1" "--workers 1 --sync-work 1 --visibility-thread 0")
for mode in "${modes[@]}"; do
  dir=$work/png_${mode// /_}
  walk --frames 6 --png-dir "$dir" $mode --stats "$dir.json" > /dev/null || fail "walk $mode"
done
python3 - "$work/png_--workers_1_--sync-work_1.json" <<'PY' || fail "--sync-work 1 with V"
import json, sys
v = json.load(open(sys.argv[1]))["visibility"]
assert v["thread"] and v["planned_on_gl_thread"] == 0 and v["overlapped_frames"] == 0, v
PY
for mode in "${modes[@]:1}"; do
  for f in "$work"/png_--workers_0/frame_*.png; do
    "$build/tests/image_compare" "$f" "$work/png_${mode// /_}/$(basename "$f")" \
      --level 0 --max-fraction 0 > /dev/null || fail "$(basename "$f"): $mode differs"
  done
done

# A starved budget (--target-ms 2 on a 1,200-patch showroom of the sample
# teapot and generated parts, walked through): surfaces are passed over
# and their loops kept; a mesh made inside such loops must be labelled for
# the bound they meet, so that every mesh drawn as on time (not late) is
# within the bound. Labelled with its target instead, such meshes measured
# 0.97 and 1.16 px (of 0.5) in 2 of 3 runs; the late ones are measured
# apart.
"$build/assets/seamwalk-pack" gen showroom --patches 1200 -o "$work/room.ini" \
  --part "$src/assets/samples/teapot.txt" > /dev/null || fail "gen showroom"
"$build/assets/seamwalk-pack" build "$work/room.ini" -o "$work/room.swpack" --quiet \
  || fail "build the showroom"
box=$("$build/assets/seamwalk-pack" info --json "$work/room.swpack" | python3 -c \
  "import json, sys; b = json.load(sys.stdin)['box']; print(*(b['min'] + b['max']))") \
  || fail "seamwalk-pack info"
python3 "$src/tests/bench/walk_path.py" "$work/room.path" --box $box --up y --seconds 40 \
  > /dev/null || fail "walk_path.py"
# The walk's own meshes are what is held to no gap here and below
# (--static-levels 0); stand-ins, whose borders still leave a few gap
# points the walk does not count (at poles and corners the file left
# apart), are checked and their gaps printed by test_standins.sh.
"$walker" --pack "$work/room.swpack" --path "$work/room.path" --headless 320x240 --frames 120 \
  --measure-every 2 --memory-mb 4096 --workers 1 --sync-work 0 --target-ms 2 \
  --static-levels 0 --stats "$work/starved.json" > /dev/null || fail "starved walk"
python3 - "$work/starved.json" <<'PY' || fail "starved walk"
import json, sys
j = json.load(open(sys.argv[1]))
t = j["threads"]
print("  starved: error max %.3f px on time, %.3f px late (bound ratio max %.1f), prefetch jobs "
      "%d, cracks %d, gaps %d" % (j["error_px"]["max"], j["error_px_behind"]["max"],
                                  t["behind_ratio_max"], t["prefetch_jobs"], j["cracks_max"],
                                  j["seam_drawn"]["gaps_max"]))
assert j["error_px"]["max"] <= j["error_px"]["bound"], j["error_px"]
assert j["error_px_behind"]["samples"] > 0 and t["behind_ratio_max"] > 1
assert j["seam_drawn"]["gaps_max"] == 0 and j["seam_drawn"]["t_vertices_max"] == 0
assert j["mallocs_after_init"] == 0
PY
# The same walk at the default budget: crack-free, on-time meshes within
# the bound. With time left (nothing in view waiting) meshes out of view
# are brought to the bound at their distance (w'): 0 to 161 such jobs
# were seen here, as the machine's load left time or not, so the count is
# printed, not held (no test here proves the prefetch runs).
"$walker" --pack "$work/room.swpack" --path "$work/room.path" --headless 320x240 --frames 120 \
  --measure-every 12 --memory-mb 4096 --workers 1 --sync-work 0 --static-levels 0 \
  --stats "$work/room.json" > /dev/null || fail "walk at the default budget"
python3 - "$work/room.json" <<'PY' || fail "walk at the default budget"
import json, sys
j = json.load(open(sys.argv[1]))
t = j["threads"]
print("  default budget: prefetch jobs %d, error max %.3f px, cracks %d, gaps %d"
      % (t["prefetch_jobs"], j["error_px"]["max"], j["cracks_max"], j["seam_drawn"]["gaps_max"]))
assert j["error_px"]["max"] <= j["error_px"]["bound"], j["error_px"]
assert j["seam_drawn"]["gaps_max"] == 0 and j["seam_drawn"]["t_vertices_max"] == 0
PY

# -1 is the default, the cores less one, on the command line as in the
# config's [budgets] workers; -2 is out of the range they share.
walk --frames 2 --workers -1 > /dev/null 2>&1 || fail "--workers -1 (the cores less one): refused"
for bad in "--workers -2" "--workers 17" "--workers x" "--target-ms 0" "--sync-work 2" \
           "--visibility-thread 2"; do
  out=$(walk --frames 2 $bad 2>&1)
  [ $? -eq 2 ] || fail "$bad: exit status"
  # The first line without a pipe: under pipefail, grep -q quitting early
  # made echo die of SIGPIPE now and then (a TSan run failed on it).
  first=${out%%$'\n'*}
  [[ $first == "seamwalk: ${bad%% *}"* ]] || fail "$bad: $first"
done
need=$(walk --frames 2 --workers 0 --stats "$work/w0.json" > /dev/null &&
       python3 -c "import json; print(int(json.load(open('$work/w0.json'))['arena_bytes'] / 1048576) + 1)")
out=$(walk --frames 2 --workers 4 --sync-work 0 --memory-mb "$need" 2>&1)
[ $? -eq 1 ] || fail "too little memory for the workers: exit status"
[[ $out =~ with\ --workers\ 4\ needs\ .*\ more\ than\ --memory-mb ]] || fail "memory: $out"
echo "ok   stalled workers: frames go on crack-free; two workers: crack-free, no allocation;" \
     "V off the GL thread; --sync-work 1 draws as --workers 0; a starved budget's meshes" \
     "within the bound; bad options and memory refused"
