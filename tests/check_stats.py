#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""check_stats.py STATS.json FRAMES [--bound PX]: the stats file
holds every contract field, counts FRAMES frames, allocates nothing after
init, and measured an error within the bound the test asked for (--bound,
default seamwalk's 0.5 px; the walk must also report that bound, so a walk
that quietly ran at another one fails). Prints what it checked; exit 1
on a failure. The walk goes through the Seam Graph: the seam fields, no
crack (border vertices bit-identical to their seam vertices, no loop point
dropped), no surface the tessellator refused, and the error within the bound
beyond each surface's sewing offset (where a file's faces are apart, the
sewn border is off a face by up to the gap whatever the level of detail:
the walk measures that offset once per surface and reports it); error_px.max
itself may exceed the bound by no more than that offset. The cache's fields
are there and consistent (no more surfaces re-tessellated in a frame than
the pack has; the drawn meshes' blocks within those in use, within the pools). The seams as drawn (firmware/walk/gl/sw_seam_drawn.h): every measured
frame checked, T-vertices reported, no gap where the model has no free
border. The depth buffer's bits (16 at least) and the largest far /
near of a frame are reported."""
import json
import sys

REQUIRED = {
    "frames": None, "frame_ms": ["p50", "p90", "p99", "max"], "fps_median": None,
    "tris_per_frame": ["median", "max"], "patches": ["total", "visible_median"],
    "error_px": ["max", "p99"], "cracks_max": None, "arena_bytes": None,
    "mallocs_after_init": None, "pack_open_ms": None, "first_frame_ms": None,
}


def main():
    stats = json.load(open(sys.argv[1]))
    frames = int(sys.argv[2])
    rest = sys.argv[3:]
    bound = float(rest[rest.index("--bound") + 1]) if "--bound" in rest else 0.5
    failures = []
    for key, sub in REQUIRED.items():
        if key not in stats:
            failures.append("missing field %s" % key)
        for s in sub or []:
            if s not in stats.get(key, {}):
                failures.append("missing field %s.%s" % (key, s))
    if failures:
        print("\n".join(failures))
        return 1
    checks = [
        (stats["frames"] == frames, "frames %d == %d" % (stats["frames"], frames)),
        (stats["mallocs_after_init"] == 0, "mallocs_after_init %d == 0" % stats["mallocs_after_init"]),
        (stats["error_px"]["samples"] > 0, "error samples %d > 0" % stats["error_px"]["samples"]),
        (stats["tris_per_frame"]["max"] > 0, "tris_per_frame.max %d > 0" % stats["tris_per_frame"]["max"]),
        (stats["patches"]["visible_median"] > 0, "patches visible"),
        (stats["arena_bytes"] > 0, "arena_bytes %d > 0" % stats["arena_bytes"]),
    ]
    checks.append((abs(stats["error_px"]["bound"] - bound) <= 1e-6,
                   "the walk's bound %.4f is the one asked for, %.4f" % (stats["error_px"]["bound"],
                                                                          bound)))
    seam = stats.get("seam", {})
    beyond = seam.get("error_px_beyond_sewing_max", float("inf"))
    offset = seam.get("sewing_offset_px_max", float("inf"))
    checks.append((beyond <= bound,
                   "error_px beyond the sewing offset %.4f <= bound %.4f (error_px.max %.4f, "
                   "sewing offset up to %.4f px)" % (beyond, bound, stats["error_px"]["max"],
                                                     offset)))
    checks.append((stats["error_px"]["max"] <= bound + offset,
                   "error_px.max %.4f <= bound + sewing offset %.4f" % (stats["error_px"]["max"],
                                                                        bound + offset)))
    checks += [
        ("active_vertices_max" in seam and seam["active_vertices_min"] > 0,
         "seam fields, active vertices %s..%s" % (seam.get("active_vertices_min"),
                                                  seam.get("active_vertices_max"))),
        (stats["cracks_max"] == 0, "cracks_max %d == 0" % stats["cracks_max"]),
        (seam.get("surfaces_failed_max", 1) == 0,
         "surfaces the tessellator refused: %s" % seam.get("surfaces_failed_max")),
    ]
    cache = stats.get("cache", {})
    retess = cache.get("retessellated", {})
    checks.append(("total" in retess and 0 < retess["total"] and
                   retess["max"] <= stats["patches"]["total"] and
                   0 <= cache.get("frames_without_retess", -1) <= frames,
                   "cache fields: %s surfaces re-tessellated in all, at most %s a frame, %s "
                   "frames without" % (retess.get("total"), retess.get("max"),
                                       cache.get("frames_without_retess"))))
    # The pools' fill: the drawn meshes' blocks are among those in use,
    # within the capacity, and a walk that drew draws from them.
    pool = cache.get("pool", {})
    checks.append((all(0 < pool.get("drawn_%s_max" % k, 0) <= pool.get("used_%s_max" % k, 0)
                       <= pool.get(k, 0) for k in ("vertices", "indices")),
                   "cache pools: vertices %s drawn, %s in use of %s; indices %s, %s of %s" % (
                       pool.get("drawn_vertices_max"), pool.get("used_vertices_max"),
                       pool.get("vertices"), pool.get("drawn_indices_max"),
                       pool.get("used_indices_max"), pool.get("indices"))))
    drawn = stats.get("seam_drawn", {})
    # T-vertices are reported, not failed: the fill fans close the
    # tessellator's crossings, but a file's own T-junctions the sewing
    # leaves (the patch soup's, the boxed sphere's) and a crossing whose
    # border chain is broken at the far end are still drawn as they are.
    checks.append((drawn.get("unchecked_frames", 1) == 0 and "t_vertices_max" in drawn,
                   "seams as drawn: %s border points, %s T-vertices (one side's point on the "
                   "other's edge, not its vertex: reported), %s unchecked frames" % (
                       drawn.get("points_max"), drawn.get("t_vertices_max"),
                       drawn.get("unchecked_frames"))))
    # A gap (a point off every other border by more than rounding, within the
    # sewing tolerance of one) is a crack where the model is closed; where it
    # has a free border, the end of one near a seam looks the same.
    checks.append((drawn.get("gaps_max", 1) == 0 or drawn.get("free_points_max", 0) > 0,
                   "seams as drawn: %s gap points, %s free border points" % (
                       drawn.get("gaps_max"), drawn.get("free_points_max"))))
    depth = stats.get("depth", {})
    checks.append((depth.get("bits", 0) >= 16 and depth.get("far_over_near_max", 0) > 1,
                   "depth buffer %s bits, far / near up to %s" % (depth.get("bits"),
                                                                 depth.get("far_over_near_max"))))
    for ok, what in checks:
        print(("ok   " if ok else "FAIL ") + what)
    return 0 if all(ok for ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
