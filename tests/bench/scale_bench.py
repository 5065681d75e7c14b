#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The memory and scale benchmark, one command:
  scale_bench.py BUILD_DIR [--patches N[,N...]] [--work DIR] [--json FILE]
                 [--threads T] [--frames F] [--quick]
For each N (default 40000): `seamwalk-pack gen showroom --patches N` from the
shared parts (the hammer, the screw, the Newell teapot, NIST part 1), built
by `seamwalk-pack build` under /usr/bin/time (wall, CPU, peak resident
memory), described by `seamwalk-pack info` (the pack's bytes by section
group, runtime_bytes, bytes per seam vertex, per patch and per placed part),
then walked headless as the kiosk service runs it (--measure-every 0
--sync-work 0, default workers) round the aisles at eye height
(walk_path.py): peak resident memory of the whole process, Mesa included,
and the arena; and started three more times for one frame each (start to
first frame: median and spread). Prints each figure beside its target
(issue 26) and writes them as JSON (--json). Never fails on a figure: exit 1
only when a step fails or a figure is missing. --quick: 1,200 patches, a
few frames, for CTest.
--work DIR keeps the scenes and packs and reuses a pack newer than the
build's seamwalk-pack."""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

PARTS = ["occt_hammer.iges", "occt_screw.step", "newell_teapot.txt", "nist_mbe_pmi_1.stp"]
MIB = 1024.0 * 1024.0

# Targets by patch count: (figure, limit, unit). A figure past its limit is
# reported as missed; the benchmark does not fail on it.
TARGETS = {
    40000: [("runtime_mib", 64, "MiB"), ("pack_mb", 48, "MB"), ("walk_rss_mib", 160, "MiB"),
            ("build_s", 20, "s")],
    400000: [("runtime_mib", 256, "MiB"), ("walk_rss_mib", 512, "MiB"), ("build_s", 60, "s"),
             ("build_peak_mb", 1500, "MB"), ("first_frame_ms", 300, "ms")],
}

# Section groups of `info --json`'s sections, by name prefix.
GROUPS = [("seam graph", "SEAM"), ("static levels", "LEVEL"), ("part levels", "PART_LEVEL"),
          ("super-surfaces", "SUPER"), ("instances", "INSTANCE"),
          ("trims", ("SURFACES", "TRIM_", "PATCH_DOMAINS")),
          ("patches, control points", ("PATCHES", "CONTROL", "ADJACENCY"))]


def run(cmd, log):
    with open(log, "w") as out:
        return subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT).returncode == 0


def timed(cmd, log):
    """cmd under /usr/bin/time -v: (ok, wall s, cpu s, peak MB)."""
    ok = run(["/usr/bin/time", "-v"] + cmd, log)
    text = open(log).read()

    def field(name):
        m = re.search(r"^\s*" + re.escape(name) + r": (.*)$", text, re.M)
        return m.group(1).strip() if m else None
    wall = field("Elapsed (wall clock) time (h:mm:ss or m:ss)")
    secs = 0.0
    for part in (wall or "0").split(":"):
        secs = secs * 60 + float(part)
    cpu = float(field("User time (seconds)") or 0) + float(field("System time (seconds)") or 0)
    peak = float(field("Maximum resident set size (kbytes)") or 0) / 1000.0
    return ok, secs, cpu, peak


def section_groups(info):
    out = {name: 0 for name, _ in GROUPS}
    other = 0
    for sec in info["sections"]:
        for name, prefix in GROUPS:
            if sec["name"].startswith(prefix):
                out[name] += sec["size"]
                break
        else:
            other += sec["size"]
    out["other"] = other
    return out


def shared_models():
    src = os.path.dirname(os.path.abspath(__file__))
    return os.path.normpath(os.path.join(src, "..", "..", "..", "shared", "models"))


class Scene:
    def __init__(self, a, patches, work):
        self.a, self.patches, self.work = a, patches, work
        self.tag = "showroom_%d" % patches
        self.figures, self.failures = {"patches": patches}, []

    def file(self, ext):
        return os.path.join(self.work, self.tag + ext)

    def build(self):
        tool = self.a.build + "/assets/seamwalk-pack"
        ini, pack = self.file(".ini"), self.file(".swpack")
        if os.path.exists(pack) and os.path.getmtime(pack) >= os.path.getmtime(tool) and \
                os.path.exists(self.file(".build.json")):
            self.figures.update(json.load(open(self.file(".build.json"))))
            return True
        cmd = [tool, "gen", "showroom", "--patches", str(self.patches), "-o", ini]
        for p in PARTS:
            cmd += ["--part", os.path.join(shared_models(), p)]
        if not run(cmd, ini + ".log"):
            self.failures.append("gen showroom failed (%s.log)" % ini)
            return False
        cmd = [tool, "build", ini, "-o", pack, "--quiet"]
        if self.a.threads:
            cmd += ["--threads", str(self.a.threads)]
        ok, wall, cpu, peak = timed(cmd, pack + ".log")
        if not ok:
            self.failures.append("build failed (%s.log)" % pack)
            return False
        built = {"build_s": wall, "build_cpu_s": cpu, "build_peak_mb": peak}
        json.dump(built, open(self.file(".build.json"), "w"))
        self.figures.update(built)
        return True

    def describe(self):
        tool = self.a.build + "/assets/seamwalk-pack"
        out = subprocess.run([tool, "info", "--json", self.file(".swpack")],
                             capture_output=True, text=True)
        if out.returncode != 0:
            self.failures.append("info failed: %s" % out.stderr.strip())
            return None
        info = json.loads(out.stdout)
        f = self.figures
        f["pack_mb"] = info["total_bytes"] / 1e6
        f["runtime_mib"] = info["runtime_bytes"] / MIB
        f["sections_mb"] = {k: v / 1e6 for k, v in section_groups(info).items()}
        seam = info.get("seam") or {}
        f["seam_vertices"] = seam.get("vertices", 0)
        f["bytes_per_seam_vertex"] = (seam.get("bytes", 0) / seam["vertices"]
                                      if seam.get("vertices") else None)
        f["bytes_per_patch"] = info["total_bytes"] / max(1, info["bezier_patches"])
        f["placed_parts"] = info["part_count"]
        f["bytes_per_placed_part"] = info["total_bytes"] / max(1, f["placed_parts"])
        f["stored_parts"] = info.get("prototype_count") or info["part_count"]
        return info

    def path(self, info):
        src = os.path.dirname(os.path.abspath(__file__))
        box = info["box"]["min"] + info["box"]["max"]
        up = info["up_axis"].lstrip("+-")
        cmd = [sys.executable, os.path.join(src, "walk_path.py"), self.file(".path"), "--box"] + \
              ["%.6f" % v for v in box] + ["--up", up, "--seconds", "40"]
        if self.patches == 40000:
            # the aisles of the 40,000-patch floor (walk_bench.py walks the same)
            cmd += ["--rect", "-5500", "-11000", "5500", "11000"]
        subprocess.run(cmd, check=True)

    def seamwalk(self, key, frames):
        out = self.file("." + key + ".json")
        cmd = [self.a.build + "/firmware/seamwalk", "--pack", self.file(".swpack"),
               "--path", self.file(".path"), "--headless", self.a.size,
               "--frames", str(frames), "--memory-mb", str(self.a.memory_mb),
               "--measure-every", "0", "--sync-work", "0", "--stats", out]
        if not run(cmd, out + ".log"):
            self.failures.append("seamwalk %s failed (%s.log)" % (key, out))
            return None
        return json.load(open(out))

    def walk(self):
        s = self.seamwalk("walk", self.a.frames)
        if not s:
            return
        f = self.figures
        f["walk_rss_mib"] = s["rss_kb"]["peak"] * 1024 / MIB
        f["arena_mib"] = s["arena_bytes"] / MIB
        f["arena_peak_mib"] = s["arena_peak_bytes"] / MIB
        f["frame_p50_ms"] = s["frame_ms"]["p50"]
        f["waiting_surfaces_max"] = s["threads"]["waiting_surfaces_max"]
        starts = [s["first_frame_ms"]]
        for k in range(self.a.starts):
            one = self.seamwalk("start%d" % k, 1)
            if not one:
                return
            starts.append(one["first_frame_ms"])
        f["first_frame_ms"] = statistics.median(starts)
        f["first_frame_ms_all"] = starts


def print_scene(sc):
    f = sc.figures
    print("\n%d-patch showroom: %s stored (prototypes), %s parts placed" %
          (sc.patches, f.get("stored_parts", "?"), f.get("placed_parts", "?")))
    rows = [("build", "build_s", "%.1f s wall (%.1f s CPU)" %
             (f.get("build_s", 0), f.get("build_cpu_s", 0))),
            ("build peak", "build_peak_mb", "%.0f MB" % f.get("build_peak_mb", 0)),
            ("pack", "pack_mb", "%.1f MB" % f.get("pack_mb", 0)),
            ("runtime_bytes", "runtime_mib", "%.1f MiB" % f.get("runtime_mib", 0)),
            ("arena (walk)", "arena_mib", "%.1f MiB" % f.get("arena_mib", 0)),
            ("peak RSS walking", "walk_rss_mib", "%.1f MiB" % f.get("walk_rss_mib", 0)),
            ("first frame", "first_frame_ms", "%.0f ms median of %s" %
             (f.get("first_frame_ms", 0), f.get("first_frame_ms_all")))]
    limits = {k: (v, u) for k, v, u in TARGETS.get(sc.patches, [])}
    for label, key, text in rows:
        target = ""
        if key in limits and key in f:
            lim, unit = limits[key]
            target = "target <= %g %s: %s" % (lim, unit, "met" if f[key] <= lim else "MISSED")
        print("  %-18s %-40s %s" % (label, text, target))
    for name, mb in (f.get("sections_mb") or {}).items():
        print("    %-24s %8.1f MB" % (name, mb))
    if f.get("bytes_per_seam_vertex"):
        print("  bytes per seam vertex %.1f, per patch %.0f, per placed part %.0f" %
              (f["bytes_per_seam_vertex"], f["bytes_per_patch"], f["bytes_per_placed_part"]))
    print("  surfaces left undrawn (waiting_surfaces_max) %s" % f.get("waiting_surfaces_max"))
    for msg in sc.failures:
        print("  scale_bench: FAIL: %s" % msg)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--patches", default="40000")
    ap.add_argument("--work")
    ap.add_argument("--json")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--frames", type=int, default=600)
    ap.add_argument("--starts", type=int, default=3)
    ap.add_argument("--size", default="1280x720")
    ap.add_argument("--memory-mb", type=int, default=16384)
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    a.build = os.path.abspath(a.build)
    if a.quick:
        a.patches, a.frames, a.starts, a.size = "1200", 8, 1, "320x240"
    if not os.path.isdir(shared_models()):
        print("scale_bench: %s is missing: the shared parts are needed" % shared_models())
        return 77
    work = a.work or tempfile.mkdtemp(prefix="scale_bench.")
    os.makedirs(work, exist_ok=True)
    scenes, failed = [], False
    for n in [int(x) for x in a.patches.split(",")]:
        sc = Scene(a, n, work)
        if sc.build():
            info = sc.describe()
            if info:
                sc.path(info)
                sc.walk()
        for key in ("build_s", "pack_mb", "runtime_mib", "walk_rss_mib", "first_frame_ms"):
            if key not in sc.figures and not sc.failures:
                sc.failures.append("figure %s missing" % key)
        print_scene(sc)
        failed = failed or bool(sc.failures)
        scenes.append({"figures": sc.figures, "failures": sc.failures,
                       "targets": {k: v for k, v, _ in TARGETS.get(n, [])}})
    if a.json:
        with open(a.json, "w") as out:
            json.dump({"scenes": scenes, "size": a.size, "frames": a.frames}, out, indent=1)
        print("scale_bench: JSON in %s" % a.json)
    print("scale_bench: %s" % ("FAIL" if failed else "done"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
