#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The walkthrough benchmark (issue 10, item 7), one command:
  walk_bench.py BUILD_DIR [--quick] [--work DIR] [--json FILE] [--plot FILE.png]
                [--scenes showroom,courtyard]
Two scenes, each on a fixed closed walk at eye height (walk_path.py) at
1280x720:
  showroom   `seamwalk-pack gen showroom --patches 40000` from real parts in
             ../shared/models (the hammer, the screw, the Newell teapot, NIST
             part 1), walked round the aisles;
  courtyard  tests/gen_soup.py's patch soup of 130 x 130 cells (about 40,000
             patches, no shared topology), walked round its middle;
and on each, side by side:
  1 seamwalk as built          } the same seamwalk binary; the flags of each
  2 seamwalk single-threaded   } row are AS_BUILT_FLAGS and SINGLE_FLAGS below
  3 uniform: every visible patch on one S x S grid each frame
    (walk_baseline --mode uniform), S searched until its measured error max
    is at most seamwalk's (row 1);
  4 GLU's NURBS tessellator re-tessellating every visible surface each frame
    at seamwalk's pixel tolerance (walk_baseline --mode glu), drawn through
    the same renderer.
Every row writes seamwalk's stats file and is measured the same way: frame
time without the measuring, triangles per frame, error (every drawn
triangle against the exact surface, on screen), cracks (the drawn borders
against each other, firmware/walk/gl/sw_seam_drawn.h: gaps), resident memory (peak).
The baselines are slow, so they draw every K-th frame of the path (said in
the table) and GLU stops after a time limit. Before the rows, seamwalk is
started 9 more times for one frame each (start to first frame: median and
spread), and row 1's walk is run once more measuring nothing (the frame
times a kiosk sees: measuring a frame lets the workers get ahead, so the
measured walk's later frames draw finer meshes), and then judged by its
pictures (tests/walk_pictures.py): the same walk writing every 10th frame
against the reference walk of the same path with --workers 0 (every mesh
made in its frame), each pair's interior background pixels (surfaces in
view the walk left undrawn) and pixels differing, against 0 and 0.5%; the
surfaces left undrawn (threads.waiting_surfaces_max) of both walks are
printed. Then the whole model in view (--orbit, measuring nothing, as built
and with --workers 0): its triangles a frame against the patches, and each
static level's reduction of triangles (seamwalk-pack info). Prints the
table and the
ratios against the issue's targets, writes the JSON (--json) and a PNG of
frame time along the path (--plot, gnuplot). Never fails on timing or on
the pictures' figures: exit 1 only when a run fails or a figure is missing.
--quick: a smoke run (small scenes, 320x240, a few frames, every 2nd
pictured), for CTest.
--work DIR keeps the generated scenes and packs there and reuses them (a
pack older than the build's seamwalk-pack is built again)."""
import argparse
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

# ---- The two seamwalk rows: the same binary, flags set here and nowhere else.
# As built: the default workers (the cores less one) with the budgets holding
# the default --target-ms, never waiting for the work (--sync-work 0: under
# CTest, SEAMWALK_TEST_SYNC_WORK=1 would make each frame wait). Single:
# every mesh made in the frame on the GL thread.
AS_BUILT_FLAGS = ["--sync-work", "0"]
SINGLE_FLAGS = ["--workers", "0"]

# The baselines draw every 40th frame of the walk, all of them measured
# (measuring a uniform grid of millions of triangles takes tens of seconds a
# frame), and stop at the first frame that starts past these many seconds.
UNIFORM_MAX_S = 75
GLU_MAX_S = 120

TARGETS = {"first_frame_ms_median": 300.0, "frame_p50_ms": 16.7, "frame_p99_ms": 33.0,
           "error_max_px": 1.0, "cracks": 0, "glu_speedup": 100.0, "tris_over_uniform": 0.2,
           "interior_background_px": 0, "differing_fraction": 0.005}
PARTS = ["occt_hammer.iges", "occt_screw.step", "newell_teapot.txt", "nist_mbe_pmi_1.stp"]


def run(cmd, log):
    """Runs cmd, output to log; True when it exits 0."""
    with open(log, "w") as out:
        return subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT).returncode == 0


def pack_info(build, pack):
    out = subprocess.run([build + "/assets/seamwalk-pack", "info", "--json", pack],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def make_scene(a, name, work):
    """The scene's pack and camera path (made once per --work folder)."""
    tool = a.build + "/assets/seamwalk-pack"
    src = os.path.dirname(os.path.abspath(__file__))
    shared = os.path.normpath(os.path.join(src, "..", "..", "..", "shared", "models"))
    q = a.quick
    tag = "%s_%s" % (name, "quick" if q else "full")
    pack, path = os.path.join(work, tag + ".swpack"), os.path.join(work, tag + ".path")
    # A pack built by an older seamwalk-pack than this build's lacks what
    # the builder makes now (a walk_bench once measured part levels on and
    # off on packs without any): made again.
    if os.path.exists(pack) and os.path.getmtime(pack) < os.path.getmtime(tool):
        print("walk_bench: %s is older than %s: building it again" % (pack, tool))
        os.remove(pack)
    if not os.path.exists(pack):
        if name == "showroom":
            ini = os.path.join(work, tag + ".ini")
            cmd = [tool, "gen", "showroom", "--patches", "1200" if q else "40000", "-o", ini]
            for p in PARTS:
                cmd += ["--part", os.path.join(shared, p)]
            if not run(cmd, ini + ".log"):
                raise RuntimeError("gen showroom failed (%s.log)" % ini)
            source = ini
        else:
            source = os.path.join(work, tag + ".igs")
            if not run([sys.executable, os.path.join(src, "..", "gen_soup.py"), source,
                        "--cells", "6" if q else "130"], source + ".log"):
                raise RuntimeError("gen_soup.py failed (%s.log)" % source)
        if not run([tool, "build", source, "-o", pack, "--quiet"], pack + ".log"):
            raise RuntimeError("building %s failed (%s.log)" % (name, pack))
    info = pack_info(a.build, pack)
    box = info["box"]["min"] + info["box"]["max"]
    up = info["up_axis"].lstrip("+-")
    cmd = [sys.executable, os.path.join(src, "walk_path.py"), path, "--box"] + \
          ["%.6f" % v for v in box] + ["--up", up, "--seconds", "40"]
    if name == "showroom" and not q:
        # the aisles of gen showroom's 40,000-patch floor: 2000 mm cells in
        # blocks of 4 x 4, 3000 mm aisles, centred on x = +-5500, z = +-11000
        cmd += ["--rect", "-5500", "-11000", "5500", "11000"]
    subprocess.run(cmd, check=True)
    return pack, path, info


class Scene:
    def __init__(self, a, name, work):
        self.a, self.name, self.work = a, name, work
        self.pack, self.path, self.info = make_scene(a, name, work)
        self.rows, self.failures, self.notes = [], [], []

    def stats_file(self, key):
        return os.path.join(self.work, "%s_%s.json" % (self.name, key))

    def run_seamwalk(self, key, frames, measure_every, flags, where=None):
        """seamwalk on the scene's pack and path (or where: other camera
        flags); its stats file, or None when it failed (the log beside
        it)."""
        a = self.a
        out = self.stats_file(key)
        cmd = [a.build + "/firmware/seamwalk", "--pack", self.pack] + \
            (where or ["--path", self.path]) + ["--headless", a.size, "--frames", str(frames), "--memory-mb", "16384",
               "--measure-every", str(measure_every), "--stats", out] + flags
        return out if run(cmd, out + ".log") else None

    def seamwalk(self, key, label, flags):
        out = self.run_seamwalk(key, self.a.frames, self.a.measure_every, flags)
        return self.add_row(key, label, out is not None, out or self.stats_file(key), every=1)

    def baseline(self, key, label, mode_args, every, max_s):
        a = self.a
        out = self.stats_file(key)
        cmd = [a.build + "/tests/bench/walk_baseline", "--pack", self.pack, "--path", self.path,
               "--size", a.size, "--frames", str(a.frames), "--every", str(every),
               "--error-bins-px", "8", "--stats", out] + mode_args
        if max_s:
            cmd += ["--max-s", str(max_s)]
        ok = run(cmd, out + ".log")
        return self.add_row(key, label, ok, out, every)

    def add_row(self, key, label, ok, out, every):
        row = {"key": key, "label": label, "every": every, "ok": ok, "stats": out}
        if ok and os.path.exists(out):
            s = json.load(open(out))
            row.update(figures(s))
            missing = [k for k in ("frames", "p50", "p99", "tris", "error_max", "error_p99")
                       if row.get(k) is None]
            # With workers every measured mesh may still be coarser than asked
            # (the first frame is made at SW_SEAM_FIRST_COARSER times the
            # bound; --quick's 8 frames of a few ms can end before a batch
            # made for the bound is swapped in): its error is then all in
            # error_px_behind, and error_px has none to report.
            all_behind = row["error_samples"] == 0 and row["error_behind_samples"] > 0
            if all_behind:
                self.notes.append("%s: every measured mesh was still being remade (error in "
                                  "error_px_behind only)" % label)
            # Stand-ins drawn from a static level within the bound are kept
            # as the surface's mesh (no job), and are not measured (the pack
            # keeps no (u, v) for them): a short walk of flat patches may
            # draw nothing else. The pictures check what they show.
            standins = (s.get("threads") or {}).get("standins_max", 0)
            all_standins = row["error_samples"] == 0 and row["error_behind_samples"] == 0 and \
                standins > 0
            if all_standins:
                self.notes.append("%s: every drawn surface was a stand-in from its static level "
                                  "(not measured; see its pictures)" % label)
            if row["frames"] == 0 or missing or \
                    (row["error_samples"] == 0 and not all_behind and not all_standins):
                row["ok"] = False
                self.failures.append("%s: figures missing (%s)" % (label, ", ".join(missing) or
                                                                   "no frame or no error sample"))
            log = open(out + ".log").read()
            for line in log.splitlines():
                if line.startswith("walk_baseline: "):
                    row["baseline"] = dict(kv.split("=", 1) for kv in line.split()[1:])
        else:
            row["ok"] = False
            self.failures.append("%s: failed (see %s.log)" % (label, out))
        return row


def figures(s):
    rss = s.get("rss_kb", {})
    return {"frames": s["frames"], "p50": s["frame_ms"]["p50"], "p99": s["frame_ms"]["p99"],
            "max": s["frame_ms"]["max"], "tris": s["tris_per_frame"]["median"],
            "error_max": s["error_px"]["max"], "error_p99": s["error_px"]["p99"],
            "error_samples": s["error_px"]["samples"],
            "error_behind_samples": s.get("error_px_behind", {}).get("samples", 0),
            "measured_frames": s["error_px"]["measured_frames"],
            "gaps": s["seam_drawn"]["gaps_max"], "unchecked": s["seam_drawn"]["unchecked_frames"],
            "seamwalk_cracks": s["cracks_max"], "rss_peak_mib": rss.get("peak", -1) / 1024.0,
            "arena_mib": s["arena_bytes"] / 1048576.0, "series": s.get("frame_ms_series", []),
            "first_frame_ms": s["first_frame_ms"], "mallocs_after_init": s["mallocs_after_init"],
            "lag": lag_figures(s)}


def lag_figures(s):
    """What a threaded walk shows while its work catches up (None without
    workers): surfaces in view not drawn yet, drawn coarser, how far."""
    t, v = s.get("threads"), s.get("visibility")
    if not t or not t.get("workers"):
        return None
    behind = s.get("error_px_behind", {})
    return {"waiting_max": t["waiting_surfaces_max"], "behind_max": t["behind_surfaces_max"],
            "behind_ratio_max": t["behind_ratio_max"], "frames_behind_max": t["frames_behind_max"],
            "error_behind_max": behind.get("max", 0.0), "prefetch_jobs": t.get("prefetch_jobs", 0),
            "visibility_ms_p50": v["ms"]["p50"] if v else None,
            "plan_wait_ms_p50": v["plan_wait_ms"]["p50"] if v else None,
            "plan_wait_ms_p99": v["plan_wait_ms"]["p99"] if v else None,
            "visibility_thread": v["thread"] if v else False}


def search_uniform(scene, target, every):
    """The coarsest S whose measured error max is <= target: a bracket
    [lo fails, hi meets] narrowed by the error's 1/S^2 law, at most six
    runs. Every run is a full row (a fine grid stops at UNIFORM_MAX_S, so it
    may measure fewer frames); the one at the answer is kept."""
    a = scene.a
    lo, hi, s, tried, rows = 0, 256, 4 if a.quick else 8, [], {}
    for _ in range(3 if a.quick else 4):
        row = scene.baseline("uniform_%d" % s, "uniform %dx%d" % (s, s),
                             ["--mode", "uniform", "--segments", str(s)], every,
                             0 if a.quick else UNIFORM_MAX_S)
        rows[s] = row
        if not row["ok"]:
            return row, tried
        e = row["error_max"]
        tried.append((s, e))
        if e <= target:
            hi = s
        else:
            lo = s
        if hi - lo <= 1 or (lo == 255 and hi == 256):
            break
        guess = math.ceil(s * math.sqrt(e / target)) if target > 0 else hi
        s = min(max(guess, lo + 1), hi - 1, 255)
    best = rows.get(hi) or rows[max(rows)]
    if hi == 256:
        scene.notes.append("no grid up to 255 x 255 reaches seamwalk's error: the finest tried "
                           "is shown")
    return best, tried


def start_times(sc, runs):
    """Program start to first frame (first_frame_ms, the first frame's
    measuring left out as in every frame) of runs separate starts, back to
    back: one start is one sample of a noisy figure (a start that comes
    after a pause pays for memory the machine had handed back), so the
    median and the spread are reported. The walk's own start is one more."""
    times = []
    for k in range(runs):
        out = sc.run_seamwalk("start%d" % k, 1, sc.a.measure_every, AS_BUILT_FLAGS)
        if not out:
            sc.failures.append("start %d failed (%s.log)" % (k, sc.stats_file("start%d" % k)))
            return None
        with open(out) as f:
            times.append(json.load(f)["first_frame_ms"])
    return {"runs": runs, "ms": times, "median": statistics.median(times),
            "min": min(times), "max": max(times)}


def unmeasured_walk(sc):
    """Row 1's walk measuring nothing (--measure-every 0, as the kiosk
    service runs): while the GL thread measures a frame the workers get
    ahead, and the frames after it draw finer meshes, so the measured walk's
    frame times are not the kiosk's. Frame times, triangles, the surfaces
    in view left undrawn, and its pictures against the reference
    (walk_pictures)."""
    out = sc.run_seamwalk("unmeasured", sc.a.frames, 0, AS_BUILT_FLAGS)
    if not out:
        sc.failures.append("the walk measuring nothing failed (%s.log)"
                           % sc.stats_file("unmeasured"))
        return None
    with open(out) as f:
        s = json.load(f)
    if s["error_px"]["measured_frames"] != 0:
        sc.failures.append("the walk measuring nothing measured %d frames"
                           % s["error_px"]["measured_frames"])
        return None
    return {"p50": s["frame_ms"]["p50"], "p99": s["frame_ms"]["p99"],
            "tris": s["tris_per_frame"]["median"], "frames": s["frames"],
            "waiting_surfaces_max": s["threads"]["waiting_surfaces_max"],
            "standins_max": s["threads"]["standins_max"],
            "static_levels_off": walk_without(sc, "unmeasured_no_levels", "--static-levels"),
            "part_levels_off": walk_without(sc, "unmeasured_no_part_levels", "--part-levels"),
            "leaner_standins_off": walk_without(sc, "unmeasured_no_leaner",
                                                "--leaner-standins"),
            "pictures": walk_pictures(sc)}


# The rows walk_without runs, printed against the walk as built: the
# option turned off, what it does, and the JSON key (unmeasured_walk.KEY).
WITHOUT_ROWS = [("--static-levels", "static levels (stand-ins for meshes not made yet)",
                 "static_levels_off"),
                ("--part-levels", "part levels (far parts drawn whole)", "part_levels_off"),
                ("--leaner-standins", "leaner meshes for stand-ins finer than needed",
                 "leaner_standins_off")]


def walk_without(sc, name, option):
    """The same walk measuring nothing with OPTION 0, same path, same run:
    the row to hold that part's cost and gain against (--static-levels 0:
    a surface whose mesh is not made yet waits, undrawn)."""
    out = sc.run_seamwalk(name, sc.a.frames, 0, AS_BUILT_FLAGS + [option, "0"])
    if not out:
        sc.failures.append("the walk with %s 0 failed (%s.log)" % (option, sc.stats_file(name)))
        return None
    with open(out) as f:
        s = json.load(f)
    return {"p50": s["frame_ms"]["p50"], "p99": s["frame_ms"]["p99"],
            "tris": s["tris_per_frame"]["median"],
            "waiting_surfaces_max": s["threads"]["waiting_surfaces_max"]}


def orbit_far_end(sc):
    """The whole model in view: --orbit (a circle round it that keeps all of
    it on screen), measuring nothing, as built and with --workers 0, and
    the triangles a frame of each against the pack's patches (paper 000:
    fewer than 2n for n patches; the issue asks for fewer than n)."""
    frames = 4 if sc.a.quick else 16
    out = {"frames": frames, "patches": sc.info["bezier_patches"]}
    for key, flags in (("orbit", AS_BUILT_FLAGS), ("orbit_single", SINGLE_FLAGS)):
        js = sc.run_seamwalk(key, frames, 0, flags, where=["--orbit"])
        if not js:
            sc.failures.append("the orbit (%s) failed (%s.log)" % (" ".join(flags),
                                                                    sc.stats_file(key)))
            return None
        with open(js) as f:
            s = json.load(f)
        out[key] = {"tris": s["tris_per_frame"]["median"], "tris_max": s["tris_per_frame"]["max"],
                    "p50": s["frame_ms"]["p50"],
                    "standins_max": s["threads"]["standins_max"] if s.get("threads") else 0,
                    "waiting_surfaces_max": s["threads"]["waiting_surfaces_max"]
                    if s.get("threads") else 0}
    return out


def level_reductions(info):
    """Each static level's triangles against the same surfaces' level one
    finer (seamwalk-pack info), as fractions fewer; [] without levels."""
    levels = info.get("levels") or {}
    return [1 - r["triangles"] / r["triangles_before"] for r in levels.get("ranks", [])
            if r.get("triangles_before")]


PICTURE_KEYS = ("frames_compared", "interior_background_px_max", "interior_background_frame",
                "differing_fraction_max", "differing_frame", "inside_px_max")


def walk_pictures(sc):
    """The walk measuring nothing once more, writing every 10th frame (2nd
    with --quick), against the same path with --workers 0 at the same bound
    (tests/walk_pictures.py, its exit 1 a figure, not a failure): the
    largest interior background and differing fraction over the frames, and
    the undrawn surfaces of this walk (a picture stops the GL thread while
    the workers go on, so this walk is not the one timed above)."""
    a = sc.a
    key = "pictures"
    out, js = os.path.join(sc.work, "%s_%s" % (sc.name, key)), sc.stats_file(key)
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "walk_pictures.py")
    cmd = [sys.executable, script, sc.pack, sc.path, a.build, out, a.size, str(a.frames),
           "--every", "2" if a.quick else "10", "--memory-mb", "16384", "--json", js]
    with open(js + ".log", "w") as log:
        rc = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT).returncode
    if rc not in (0, 1) or not os.path.exists(js):
        sc.failures.append("the pictures of the walk measuring nothing failed (%s.log)" % js)
        return None
    with open(js) as f:
        p = json.load(f)
    missing = [k for k in PICTURE_KEYS if p.get(k) is None]
    if missing or p["test_walk"].get("waiting_surfaces_max") is None:
        sc.failures.append("pictures: figures missing (%s)" % ", ".join(missing or
                                                                    ["waiting_surfaces_max"]))
        return None
    figures = {k: p[k] for k in PICTURE_KEYS}
    figures.update({"every": p["every"], "frames_with_model": p["frames_with_model"],
                    "waiting_surfaces_max": p["test_walk"]["waiting_surfaces_max"],
                    "dir": out})
    return figures


def run_scene(a, name, work):
    sc = Scene(a, name, work)
    sc.start = start_times(sc, 3 if a.quick else 9)
    sc.unmeasured = unmeasured_walk(sc)
    sc.orbit = orbit_far_end(sc)
    same = AS_BUILT_FLAGS == SINGLE_FLAGS
    r1 = sc.seamwalk("seamwalk", "seamwalk as built", AS_BUILT_FLAGS)
    r2 = sc.seamwalk("seamwalk_single", "seamwalk single-threaded", SINGLE_FLAGS)
    if same:
        sc.notes.append("rows 1 and 2 ran the same flags (AS_BUILT_FLAGS == SINGLE_FLAGS)")
    # The error the uniform grid must reach: seamwalk's, as built, or the
    # single-threaded walk's (the same bound) when no mesh as built was
    # measured at its bound (add_row).
    measured = [r for r in (r1, r2) if r["ok"] and r["error_samples"] > 0]
    target = measured[0]["error_max"] if measured else None
    if measured and measured[0] is r2:
        sc.notes.append("uniform matched to the single-threaded row's error")
    uniform_every = 4 if a.quick else 40
    if target is not None:
        r3, tried = search_uniform(sc, target, uniform_every)
        sc.uniform_tried = tried
    else:
        r3 = {"key": "uniform", "label": "uniform", "ok": False, "every": uniform_every}
        sc.failures.append("uniform: no seamwalk error to match")
        sc.uniform_tried = []
    glu_every = 4 if a.quick else 40
    r4 = sc.baseline("glu", "GLU, every frame", ["--mode", "glu", "--tolerance-px", "0.5"],
                     glu_every, 0 if a.quick else GLU_MAX_S)
    sc.rows = [r1, r2, r3, r4]
    return sc


def ratios(sc):
    r1, _, r3, r4 = sc.rows
    out = {}
    if sc.start:
        out["first_frame_ms_median"] = sc.start["median"]
    if sc.unmeasured:
        out["unmeasured_frame_p50_ms"] = sc.unmeasured["p50"]
        out["unmeasured_frame_p99_ms"] = sc.unmeasured["p99"]
        p = sc.unmeasured["pictures"]
        if p:
            out["interior_background_px"] = p["interior_background_px_max"]
            out["differing_pct"] = 100 * p["differing_fraction_max"]
    if sc.orbit:
        out["orbit_tris_over_patches"] = sc.orbit["orbit"]["tris"] / sc.orbit["patches"]
    reductions = level_reductions(sc.info)
    if reductions:
        out["level_reduction_min_pct"] = 100 * min(reductions)
        out["level_reduction_max_pct"] = 100 * max(reductions)
    if r1["ok"]:
        out["frame_p50_ms"] = r1["p50"]
        out["frame_p99_ms"] = r1["p99"]
        if r1["error_samples"] > 0:
            out["error_max_px"] = r1["error_max"]
        out["cracks"] = r1["gaps"] + r1["seamwalk_cracks"]
        if r4["ok"] and r1["p50"] > 0:
            out["glu_speedup"] = r4["p50"] / r1["p50"]
        if r3["ok"] and r3["tris"] > 0:
            out["tris_over_uniform"] = r1["tris"] / r3["tris"]
    return out


def frames_text(a, r):
    if not r["ok"]:
        return "-"
    if r["every"] == 1:
        return "%d" % r["frames"]
    text = "%d of %d" % (r["frames"], a.frames)
    if r.get("baseline", {}).get("stopped_early") == "1":
        text += "*"
    return text


def cracks_text(r):
    """The drawn gaps; n/a when no measured frame's borders fit the check,
    >= when some did not."""
    if r["unchecked"] >= r["measured_frames"]:
        return "n/a"
    return ("%d" if r["unchecked"] == 0 else ">=%d") % r["gaps"]


def print_scene(a, sc):
    info = sc.info
    print("\n%s: %d Bezier patches, %d surfaces; %s, a closed walk of %d frames (%s)"
          % (sc.name, info["bezier_patches"], info["surfaces"], a.size, a.frames,
             os.path.basename(sc.path)))
    head = ("%-26s %10s %9s %9s %11s %9s %9s %7s %9s"
            % ("row", "frames", "p50 ms", "p99 ms", "tris/frame", "err max", "err p99",
               "cracks", "RSS MiB"))
    print(head)
    print("-" * len(head))
    for r in sc.rows:
        if not r["ok"]:
            print("%-26s FAILED" % r["label"])
            continue
        print("%-26s %10s %9.1f %9.1f %11d %9.3f %9.3f %7s %9.0f"
              % (r["label"], frames_text(a, r), r["p50"], r["p99"], r["tris"], r["error_max"],
                 r["error_p99"], cracks_text(r), r["rss_peak_mib"]))
    r1, _, r3, r4 = sc.rows
    if r1["ok"]:
        print("seamwalk: its own crack count %d (border vertices off their seam vertex, dropped "
              "loop points, holes); arena %.0f MiB; first frame %.0f ms after start"
              % (r1["seamwalk_cracks"], r1["arena_mib"], r1["first_frame_ms"]))
    if sc.unmeasured:
        u = sc.unmeasured
        print("seamwalk as built, measuring nothing (--measure-every 0, as the kiosk service "
              "runs): frame p50 %.1f ms, p99 %.1f ms, %d triangles a frame (median); up to %d "
              "surfaces in view left undrawn (no mesh yet); its error is not measured"
              % (u["p50"], u["p99"], u["tris"], u["waiting_surfaces_max"]))
        print("  up to %d stand-ins a frame" % u["standins_max"])
        for option, what, key in WITHOUT_ROWS:
            off = u.get(key)
            if off:
                print("  %s on against off (%s 0), same path: frame p50 %.1f against %.1f ms, "
                      "p99 %.1f against %.1f ms, %d against %d triangles, undrawn max %d "
                      "against %d"
                      % (what, option, u["p50"], off["p50"], u["p99"], off["p99"], u["tris"],
                         off["tris"], u["waiting_surfaces_max"], off["waiting_surfaces_max"]))
        p = u["pictures"]
        if p:
            print("  its pictures, one frame in %d (%d compared, %d with the model), against "
                  "--workers 0 on the same path: interior background px max %d (frame %d), "
                  "differing max %.3f%% of pixels (frame %d), inside shown px max %d; that walk "
                  "left up to %d surfaces undrawn (a picture stops the GL thread while the "
                  "workers go on); pictures in %s"
                  % (p["every"], p["frames_compared"], p["frames_with_model"],
                     p["interior_background_px_max"], p["interior_background_frame"],
                     100 * p["differing_fraction_max"], p["differing_frame"], p["inside_px_max"],
                     p["waiting_surfaces_max"], p["dir"]))
    if sc.orbit:
        o, one = sc.orbit["orbit"], sc.orbit["orbit_single"]
        print("seamwalk at the far end of an orbit (--orbit, %d frames, the whole model in view, "
              "measuring nothing): %d triangles a frame (median; max %d), up to %d stand-ins, "
              "%d undrawn; with --workers 0 %d (median); the pack has %d patches"
              % (sc.orbit["frames"], o["tris"], o["tris_max"], o["standins_max"],
                 o["waiting_surfaces_max"], one["tris"], sc.orbit["patches"]))
    reductions = level_reductions(sc.info)
    if reductions:
        print("static levels: each level's triangles fewer than the level before of the same "
              "surfaces by %s" % ", ".join("%.0f%%" % (100 * r) for r in reductions))
    if sc.start:
        t = sc.start
        print("seamwalk: start to first frame over %d more starts, back to back: median %.0f ms "
              "(%.0f-%.0f): %s" % (t["runs"], t["median"], t["min"], t["max"],
                                   " ".join("%.0f" % v for v in t["ms"])))
    lag = r1.get("lag") if r1["ok"] else None
    if lag:
        print("seamwalk as built, while its work catches up: up to %d surfaces in view not drawn "
              "yet (no mesh), %d drawn coarser (up to %.1fx the bound, %d frames behind; their "
              "error max %.3f px, apart from the column); %d meshes fetched ahead out of view; "
              "visibility thread %s: its plan p50 %.1f ms, the GL thread waited for it p50 %.1f, "
              "p99 %.1f ms" % (lag["waiting_max"], lag["behind_max"], lag["behind_ratio_max"],
                               lag["frames_behind_max"], lag["error_behind_max"],
                               lag["prefetch_jobs"], "on" if lag["visibility_thread"] else "off",
                               lag["visibility_ms_p50"], lag["plan_wait_ms_p50"],
                               lag["plan_wait_ms_p99"]))
    if r3["ok"]:
        print("uniform: every %dth frame of the path%s; grids tried (S, error max px): %s"
              % (r3["every"], " (* stopped at the time limit)"
                 if r3.get("baseline", {}).get("stopped_early") == "1" else "",
                 ", ".join("%d: %.3f" % t for t in sc.uniform_tried)))
    if r4["ok"]:
        b = r4.get("baseline", {})
        print("GLU: every %dth frame%s; %s surfaces GLU cannot take as one NURBS left out; "
              "surfaces with a GLU error or output dropped, most in a frame: %s"
              % (r4["every"], " (* stopped at the time limit)" if b.get("stopped_early") == "1"
                 else "", b.get("glu_skipped_surfaces", "?"), b.get("failed_surfaces_max", "?")))
    if any(r["ok"] and r["unchecked"] for r in sc.rows):
        print("cracks: n/a or >=: the drawn borders of some measured frames overflowed the "
              "drawn-seam check (2^18 edges in seamwalk, 2^20 in the baselines) and were not "
              "checked")
    print("RSS: the process's peak resident memory, measuring included (the error samples' "
          "histogram, the drawn-seam check)")
    for n in sc.notes:
        print("note: " + n)
    sc.ratio = ratios(sc)
    t = TARGETS
    q = sc.ratio
    def line(k, text, ok):
        if k in q:
            print("  %-58s %s" % (text % q[k], "meets" if ok(q[k]) else "misses"))
    print("against the issue's targets (row 1):")
    line("first_frame_ms_median", "start to first frame %.0f ms, median (target <= 300)",
         lambda v: v <= t["first_frame_ms_median"])
    line("frame_p50_ms", "frame median %.1f ms (target <= 16.7)", lambda v: v <= t["frame_p50_ms"])
    line("frame_p99_ms", "frame p99 %.1f ms (target <= 33)", lambda v: v <= t["frame_p99_ms"])
    line("unmeasured_frame_p50_ms", "measuring nothing: frame median %.1f ms (<= 16.7)",
         lambda v: v <= t["frame_p50_ms"])
    line("unmeasured_frame_p99_ms", "measuring nothing: frame p99 %.1f ms (<= 33)",
         lambda v: v <= t["frame_p99_ms"])
    line("interior_background_px", "measuring nothing: %d interior background px (target 0)",
         lambda v: v == t["interior_background_px"])
    line("differing_pct", "measuring nothing: %.3f%% of pixels differ (<= 0.5%%)",
         lambda v: v <= 100 * t["differing_fraction"])
    line("orbit_tris_over_patches", "far end of an orbit: %.2f triangles a patch (< 1)",
         lambda v: v < 1)
    line("level_reduction_min_pct", "static levels: reduction per level at least %.0f%% "
         "(30-80%%)", lambda v: 30 <= v <= 80)
    line("level_reduction_max_pct", "static levels: reduction per level at most %.0f%% "
         "(30-80%%)", lambda v: 30 <= v <= 80)
    line("error_max_px", "error max %.3f px at bound 0.5 (target <= 1)",
         lambda v: v <= t["error_max_px"])
    line("cracks", "cracks %d (drawn gaps + seamwalk's own; target 0)", lambda v: v == 0)
    line("glu_speedup", "%.1fx GLU's frame rate (p50 ratio; target >= 100x)",
         lambda v: v >= t["glu_speedup"])
    line("tris_over_uniform", "%.3f of uniform's triangles (target <= 0.2)",
         lambda v: v <= t["tris_over_uniform"])


def plot(a, scenes, png):
    """Frame time along the path, one panel per scene, log scale."""
    gp = shutil.which("gnuplot")
    if not gp:
        return "gnuplot not found (cmake/install-deps.sh installs gnuplot-nox)"
    script = ["set terminal png size 1200,%d" % (420 * len(scenes)), "set output '%s'" % png,
              "set multiplot layout %d,1" % len(scenes), "set logscale y",
              "set xlabel 'frame along the path'", "set ylabel 'frame ms'", "set grid",
              "set key outside right"]
    for sc in scenes:
        plots = []
        for r in sc.rows:
            if not r["ok"] or not r["series"]:
                continue
            data = os.path.join(sc.work, "%s_%s.dat" % (sc.name, r["key"]))
            with open(data, "w") as f:
                for i, ms in enumerate(r["series"]):
                    f.write("%d %g\n" % (i * r["every"], max(ms, 0.01)))
            plots.append("'%s' using 1:2 with linespoints title '%s'" % (data, r["label"]))
        script.append("set title '%s, %s'" % (sc.name, a.size))
        script.append("plot " + ", ".join(plots) if plots else "plot 1 title 'no data'")
    script.append("unset multiplot")
    gpfile = os.path.join(scenes[0].work, "walk_bench.gp")
    open(gpfile, "w").write("\n".join(script) + "\n")
    r = subprocess.run([gp, gpfile], capture_output=True, text=True)
    if r.returncode != 0 or not os.path.exists(png) or os.path.getsize(png) == 0:
        return "gnuplot failed: " + r.stderr.strip()[-300:]
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--work")
    ap.add_argument("--json")
    ap.add_argument("--plot")
    ap.add_argument("--scenes", default="showroom,courtyard")
    a = ap.parse_args()
    a.build = os.path.abspath(a.build)
    # Measuring a seamwalk frame costs more than drawing it (tens of millions
    # of samples on the showroom): every 12th, 10 of the 120.
    a.size, a.frames, a.measure_every = ("320x240", 8, 2) if a.quick else ("1280x720", 120, 12)
    shared = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                           "..", "..", "shared", "models"))
    if not all(os.path.exists(os.path.join(shared, p)) for p in PARTS):
        print("walk_bench: skipped: the showroom's parts are not in %s" % shared)
        return 77
    work = a.work or tempfile.mkdtemp(prefix="swwalkbench.")
    os.makedirs(work, exist_ok=True)
    png = a.plot or os.path.join(work, "walk_bench.png")
    print("walk_bench: %s, %d frames along each path%s; work in %s"
          % (a.size, a.frames, " (--quick)" if a.quick else "", work))
    scenes, failures = [], []
    for name in a.scenes.split(","):
        try:
            sc = run_scene(a, name, work)
        except (RuntimeError, subprocess.CalledProcessError) as e:
            failures.append("%s: %s" % (name, e))
            continue
        print_scene(a, sc)
        scenes.append(sc)
        failures += ["%s: %s" % (name, f) for f in sc.failures]
    if scenes:
        problem = plot(a, scenes, png)
        if problem:
            failures.append("plot: " + problem)
        else:
            print("\nwalk_bench: frame time along the path in %s" % png)
    result = {"bench": "walk", "viewport": a.size, "frames": a.frames, "quick": a.quick,
              "as_built_flags": AS_BUILT_FLAGS, "single_flags": SINGLE_FLAGS,
              "targets": TARGETS, "failures": failures,
              "scenes": {sc.name: {"patches": sc.info["bezier_patches"],
                                   "surfaces": sc.info["surfaces"], "notes": sc.notes,
                                   "uniform_tried": sc.uniform_tried,
                                   "start_to_first_frame": sc.start,
                                   "unmeasured_walk": sc.unmeasured,
                                   "orbit_far_end": sc.orbit,
                                   "level_reductions": level_reductions(sc.info),
                                   "rows": [{k: v for k, v in r.items() if k != "series"}
                                            for r in sc.rows],
                                   "ratios": sc.ratio} for sc in scenes}}
    if a.json:
        json.dump(result, open(a.json, "w"), indent=1)
        print("walk_bench: JSON in %s" % a.json)
    for f in failures:
        print("walk_bench: FAIL: " + f)
    if not a.work and a.plot and not failures:  # kept on failure: the logs are there
        shutil.rmtree(work, ignore_errors=True)
    print("walk_bench: %s" % ("failed" if failures else "done"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
