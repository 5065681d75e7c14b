#!/usr/bin/env python3
"""check_stats.py STATS.json FRAMES: the stats file holds every contract field,
counts FRAMES frames, allocates nothing after init, and measured an error
within the configured bound. Prints what it checked; exit 1 on a failure."""
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
        (stats["error_px"]["max"] <= stats["error_px"]["bound"],
         "error_px.max %.4f <= bound %.4f" % (stats["error_px"]["max"], stats["error_px"]["bound"])),
        (stats["error_px"]["samples"] > 0, "error samples %d > 0" % stats["error_px"]["samples"]),
        (stats["tris_per_frame"]["max"] > 0, "tris_per_frame.max %d > 0" % stats["tris_per_frame"]["max"]),
        (stats["patches"]["visible_median"] > 0, "patches visible"),
        (stats["arena_bytes"] > 0, "arena_bytes %d > 0" % stats["arena_bytes"]),
    ]
    for ok, what in checks:
        print(("ok   " if ok else "FAIL ") + what)
    return 0 if all(ok for ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
