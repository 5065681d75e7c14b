#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A walk judged by its pictures, as a person would judge it:
  walk_pictures.py PACK PATH BUILD_DIR OUT_DIR [SIZE] [FRAMES] [--every K]
                   [--workers N] [--part-levels 0|1] [--test-part-levels-coarsest 0|1]
                   [--test-drop-surface S]
                   [--test-standin-silhouettes 0|1]
                   [--max-error-px E]
                   [--memory-mb M] [--max-differing F] [--back-faces cyan|lit]
                   [--json FILE]
PACK is walked along PATH (a camera path file, or `orbit` for --orbit: the
whole model in view, where far parts are drawn from their part levels)
(FRAMES frames, default 120, headless at SIZE,
default 640x360) twice, each writing every K-th frame's picture (default 10):
  test       as the kiosk service runs it (firmware/dist/seamwalk.service): the
             default workers (the cores less one; --workers N to choose),
             measuring nothing (--measure-every 0), never waiting for the
             work (--sync-work 0: CTest's SEAMWALK_TEST_SYNC_WORK=1 would
             make each frame wait);
  reference  the same path, frames and bound with --workers 0 and
             --part-levels 0: every surface's mesh made in its frame, so
             every surface in view is drawn as the tessellator makes it.
Both are drawn over magenta (255,0,255), a colour no part has, back faces
flat cyan (0,255,255) (--back-faces lit: lit as the kiosk draws them, and
(a)'s inside count not taken), so each pair of pictures can be compared
pixel by pixel:
  (a) interior background: pixels more than 2 px inside the reference's
      model (its silhouette and contours) where the test shows the
      background (tests/image_holes.c; its notches at crossing silhouettes
      are counted apart); the test's cyan there (the inside of a solid
      showing) is counted apart too;
  (b) differing: the fraction of all pixels whose largest channel
      differs by more than 8 levels (tests/image_compare.c).
Prints each frame's figures and the largest over the frames of (a) and (b)
with their frames, against the targets 0 and 0.5%, and the test walk's
threads.waiting_surfaces_max (surfaces in view left undrawn, the most in a
frame); --json writes them. The pictures are in OUT_DIR/test and
OUT_DIR/reference, each frame's holes in red in OUT_DIR/holes.
Exit 0 when no frame has interior background (and, with --max-differing F,
none differs in more than F of its pixels), 1 when one has, 2 when a walk
or a comparison fails or no reference picture shows the model.
--test-standin-silhouettes 0: the test walk's stand-ins where a silhouette may
cross them take their level by its error alone (the mutant whose silhouettes
leave slits between columns).
--part-levels 0|1, --leaner-standins 0|1: passed to the test walk (default:
seamwalk's, on).
--test-part-levels-coarsest 1: the test walk draws every part in view from
its coarsest part level (a mutant: the comparison must see it).
--test-drop-surface S: the test walk never draws surface S (a mutant: the
comparison must see it).
Limits: writing a picture stops the GL thread (read back, PNG) while the
workers go on, so a threaded walk's pictures show it with more work done
than the same walk without pictures; and headless frames are not paced by a
display. Compare the undrawn counts of both (walk_bench prints them)."""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

MAGENTA, CYAN = "255,0,255", "0,255,255"
TARGET_DIFFERING = 0.005
LEVEL = 8


def walk(a, name, flags):
    """One walk into OUT_DIR/name (pictures), name.json (stats), name.log;
    its stats, or None when it failed."""
    out = os.path.join(a.out, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    stats = out + ".json"
    where = ["--orbit"] if a.path == "orbit" else ["--path", a.path]
    cmd = [os.path.join(a.build, "firmware", "seamwalk"), "--pack", a.pack] + where + [
           "--headless", a.size, "--frames", str(a.frames), "--measure-every", "0",
           "--background", MAGENTA, "--back-faces", CYAN if a.back_faces == "cyan" else "lit",
           "--png-dir", out,
           "--png-every", str(a.every), "--stats", stats] + flags
    if a.max_error_px is not None:
        cmd += ["--max-error-px", str(a.max_error_px)]
    if a.memory_mb is not None:
        cmd += ["--memory-mb", str(a.memory_mb)]
    with open(out + ".log", "w") as log:
        log.write(" ".join(cmd) + "\n")
        log.flush()
        rc = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT).returncode
    if rc != 0:
        print("walk_pictures: the %s walk failed (exit %d): %s" % (name, rc, tail(out + ".log")))
        return None
    with open(stats) as f:
        return json.load(f)


def tail(path, lines=3):
    with open(path) as f:
        return " | ".join(f.read().splitlines()[-lines:])


HOLES = re.compile(r": (\d+) holes, (\d+) inside in (\d+) interior pixels of the model "
                   r"\((\d+) pixels, (\d+) in TEST; margin \d+ px; (\d+) notch pixels")
DIFFER = re.compile(r": (\d+) of (\d+) pixels differ by more than")


def compare(a, frame):
    """Frame's pictures compared: its figures, or an error message."""
    name = "frame_%05d.png" % frame
    test, ref = os.path.join(a.out, "test", name), os.path.join(a.out, "reference", name)
    for p in (test, ref):
        if not os.path.exists(p):
            return "no picture %s" % p
    holes_png = os.path.join(a.out, "holes", name)
    inside = ["--inside", CYAN] if a.back_faces == "cyan" else []
    r = subprocess.run([os.path.join(a.build, "tests", "image_holes"), test, ref, MAGENTA] +
                       inside + ["--max", "1000000000", "--empty-ok", "--out", holes_png],
                       capture_output=True, text=True)
    m = HOLES.search(r.stdout)
    if r.returncode != 0 or not m:
        return "image_holes on %s: exit %d: %s" % (name, r.returncode,
                                                   (r.stdout + r.stderr).strip()[-300:])
    holes, inside, interior, model, test_model, notches = map(int, m.groups())
    r = subprocess.run([os.path.join(a.build, "tests", "image_compare"), test, ref,
                        "--level", str(LEVEL), "--max-fraction", "1"],
                       capture_output=True, text=True)
    d = DIFFER.search(r.stdout)
    if r.returncode != 0 or not d:
        return "image_compare on %s: exit %d: %s" % (name, r.returncode,
                                                     (r.stdout + r.stderr).strip()[-300:])
    differing, total = int(d.group(1)), int(d.group(2))
    return {"frame": frame, "interior_background_px": holes, "inside_px": inside,
            "notch_px": notches, "interior_px": interior, "model_px_reference": model,
            "model_px_test": test_model, "differing_px": differing,
            "differing_fraction": differing / total}


def largest(rows, key):
    """The row with the largest key (the first such frame)."""
    return max(rows, key=lambda r: (r[key], -r["frame"]))


def threads_figures(stats):
    t = stats.get("threads", {})
    return {"workers": t.get("workers", 0), "waiting_surfaces_max": t.get("waiting_surfaces_max"),
            "behind_surfaces_max": t.get("behind_surfaces_max"),
            "frame_p50_ms": stats["frame_ms"]["p50"], "frame_p99_ms": stats["frame_ms"]["p99"],
            "frames": stats["frames"]}


def parse_args(argv):
    ap = argparse.ArgumentParser(description="A walk against its reference, picture by picture.")
    ap.add_argument("pack")
    ap.add_argument("path")
    ap.add_argument("build")
    ap.add_argument("out")
    ap.add_argument("size", nargs="?", default="640x360")
    ap.add_argument("frames", nargs="?", type=int, default=120)
    ap.add_argument("--every", type=int, default=10)
    ap.add_argument("--workers", type=int)
    ap.add_argument("--test-drop-surface", type=int)
    ap.add_argument("--test-standin-silhouettes", type=int)
    ap.add_argument("--part-levels", type=int, choices=(0, 1))
    ap.add_argument("--leaner-standins", type=int, choices=(0, 1))
    ap.add_argument("--test-part-levels-coarsest", type=int, choices=(0, 1))
    ap.add_argument("--max-error-px", type=float)
    ap.add_argument("--memory-mb", type=int)
    ap.add_argument("--max-differing", type=float)
    ap.add_argument("--back-faces", choices=("cyan", "lit"), default="cyan")
    ap.add_argument("--json")
    a = ap.parse_args(argv)
    if a.frames < 1 or a.every < 1:
        ap.error("FRAMES and --every must be at least 1")
    for k in ("pack", "path", "build", "out"):
        if k != "path" or a.path != "orbit":
            setattr(a, k, os.path.abspath(getattr(a, k)))
    return a


def main(argv):
    a = parse_args(argv)
    if a.json and os.path.exists(a.json):
        os.remove(a.json)   # a failed run leaves none, not the last run's
    os.makedirs(a.out, exist_ok=True)
    shutil.rmtree(os.path.join(a.out, "holes"), ignore_errors=True)
    os.makedirs(os.path.join(a.out, "holes"))
    test_flags = ["--sync-work", "0"]
    if a.workers is not None:
        test_flags += ["--workers", str(a.workers)]
    if a.test_drop_surface is not None:
        test_flags += ["--test-drop-surface", str(a.test_drop_surface)]
    if a.part_levels is not None:
        test_flags += ["--part-levels", str(a.part_levels)]
    if a.leaner_standins is not None:
        test_flags += ["--leaner-standins", str(a.leaner_standins)]
    if a.test_part_levels_coarsest is not None:
        test_flags += ["--test-part-levels-coarsest", str(a.test_part_levels_coarsest)]
    if a.test_standin_silhouettes is not None:
        test_flags += ["--test-standin-silhouettes", str(a.test_standin_silhouettes)]
    ref_flags = ["--workers", "0", "--part-levels", "0"]
    test = walk(a, "test", test_flags)
    ref = walk(a, "reference", ref_flags)
    if test is None or ref is None:
        return 2
    rows = []
    for frame in range(0, a.frames, a.every):
        r = compare(a, frame)
        if isinstance(r, str):
            print("walk_pictures: " + r)
            return 2
        rows.append(r)
        print("  frame %4d: %6d interior background px, %6d inside, %6d notch; model %6d px "
              "(reference %6d); %6.3f%% differ" % (frame, r["interior_background_px"],
                                                 r["inside_px"], r["notch_px"], r["model_px_test"],
                                                 r["model_px_reference"],
                                                 100 * r["differing_fraction"]))
    with_model = sum(1 for r in rows if r["model_px_reference"] > 0)
    if with_model == 0:
        print("walk_pictures: no reference picture shows the model: nothing compared")
        return 2
    holes, inside = largest(rows, "interior_background_px"), largest(rows, "inside_px")
    differ = largest(rows, "differing_fraction")
    t = threads_figures(test)
    result = {"pack": a.pack, "path": a.path, "size": a.size, "frames": a.frames,
              "every": a.every, "test_flags": test_flags, "reference_flags": ref_flags,
              "back_faces": a.back_faces,
              "frames_compared": len(rows), "frames_with_model": with_model,
              "interior_background_px_max": holes["interior_background_px"],
              "interior_background_frame": holes["frame"],
              "inside_px_max": inside["inside_px"], "inside_frame": inside["frame"],
              "differing_fraction_max": differ["differing_fraction"],
              "differing_frame": differ["frame"], "test_walk": t,
              "targets": {"interior_background_px": 0, "differing_fraction": TARGET_DIFFERING},
              "max_differing": a.max_differing, "per_frame": rows}
    failed = holes["interior_background_px"] > 0 or (
        a.max_differing is not None and differ["differing_fraction"] > a.max_differing)
    result["failed"] = failed
    print("walk_pictures: %d frames compared (every %dth of %d at %s; %d show the model in the "
          "reference); test walk %s against --workers 0" % (
              len(rows), a.every, a.frames, a.size, with_model, " ".join(test_flags)))
    print("  interior background px max %d (frame %d; target 0): %s" % (
        holes["interior_background_px"], holes["frame"],
        "meets" if holes["interior_background_px"] == 0 else "misses"))
    print("  differing max %.3f%% of pixels (frame %d; target <= %.1f%%): %s" % (
        100 * differ["differing_fraction"], differ["frame"], 100 * TARGET_DIFFERING,
        "meets" if differ["differing_fraction"] <= TARGET_DIFFERING else "misses"))
    if a.back_faces == "cyan":
        print("  inside shown px max %d (frame %d: the cyan inside of a solid where the "
              "reference shows its outside; not judged)" % (inside["inside_px"], inside["frame"]))
    else:
        print("  back faces lit as the kiosk draws them: the inside of a solid not told apart")
    print("  test walk: workers %d, undrawn (waiting_surfaces_max) %s, drawn coarser "
          "(behind_surfaces_max) %s; frame p50 %.1f ms, p99 %.1f ms" % (
              t["workers"], t["waiting_surfaces_max"], t["behind_surfaces_max"],
              t["frame_p50_ms"], t["frame_p99_ms"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(result, f, indent=1)
    print("walk_pictures: %s (pictures in %s)" % ("FAILED" if failed else "ok", a.out))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
