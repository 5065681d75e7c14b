#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""One row of tests/corpus.sh: a JSON object (line 1) and the table line
(line 2) for a file, from its pack's info, its close-to-far walk's stats and
OpenCASCADE's sewing of it (each may be missing: an earlier step failed).
  corpus_row.py row NAME RESULT REASON BUILD_MS PEAK_KB INFO NEAR_FAR OCCT REQUIRE NOTE ALLOW
  corpus_row.py summary ROWS.jsonl
REASON is the step that failed ("" when none did). The result turns to
"fail" when the walk left a surface out or showed a crack (reason "walk"),
when the pack has fewer surfaces than OpenCASCADE transferred faces beyond
the faces the build named as skipped ("faces"), and (REQUIRE 1) when the
free border is over 1.05x OpenCASCADE's ("sewing"); ALLOW lists "FILE:MM"
pairs: that file may have up to MM free instead. The summary counts the
files, those ok, those failed by reason and the faces skipped."""
import json
import os
import sys


def load(path):
    if not path or not os.path.exists(path) or os.path.getsize(path) == 0:
        return None
    with open(path) as f:
        return json.load(f)


def main(argv):
    name, result, reason, ms, peak_kb, info_p, walk_p, occt_p, require, note, allow = argv[2:13]
    allowed = dict((a.rsplit(":", 1)[0], float(a.rsplit(":", 1)[1])) for a in allow.split())
    info, walk, occt = load(info_p), load(walk_p), load(occt_p)
    notes = [note] if note else []
    row = {"file": name, "result": result, "build_s": int(ms) / 1000.0,
           "peak_mb": int(peak_kb) / 1024.0}
    if reason:
        row["reason"] = reason

    def fail(why, note_text):
        if row["result"] == "ok":
            row["result"], row["reason"] = "fail", why
        notes.append(note_text)
    if info:
        row["surfaces"] = sum(p["surfaces"] for p in info["parts"])
        row["skipped_faces"] = sum(n["count"] for n in info.get("import_notes", [])
                                   if n["kind"] == "skipped" and n["what"].startswith("face "))
        border = info.get("border")
        if border:
            row["free_border"] = border["free_length"]
            row["border"] = border["length"]
            row["free_fraction"] = border["free_fraction"]
    if walk:
        seam = walk["seam"]
        row["error_px"] = seam["error_px_beyond_sewing_max"]
        row["cracks"] = walk["cracks_max"]
        row["failed_surfaces"] = seam["surfaces_failed_max"]
        if row["cracks"] or row["failed_surfaces"]:
            fail("walk", "cracks or refused surfaces")
    if occt and occt["faces"] == 0:
        notes.append("OpenCASCADE reads no faces: no sewing to compare")
    if occt and "surfaces" in row:
        row["occt_faces"] = occt["faces"]
        missing = occt["faces"] - row["surfaces"]
        if missing > row["skipped_faces"]:
            fail("faces", "%d surfaces for OpenCASCADE's %d faces, %d named as skipped"
                 % (row["surfaces"], occt["faces"], row["skipped_faces"]))
        elif row["skipped_faces"]:
            notes.append("%d faces skipped, each named" % row["skipped_faces"])
    if occt and occt["faces"] > 0:
        row["occt_free_border"] = occt["free_length"]
        row["occt_free_fraction"] = occt["free_length"] / occt["length"] if occt["length"] else 0
        if "free_border" in row:
            slack = 1e-6 * row["border"]
            limit = max(1.05 * occt["free_length"] + slack, allowed.get(name, 0.0))
            over = row["free_border"] > limit
            if not over and row["free_border"] > 1.05 * occt["free_length"] + slack:
                notes.append("free border %.4g vs OpenCASCADE's %.4g: a known shortfall, "
                             "held to %.4g" % (row["free_border"], occt["free_length"],
                                               allowed[name]))
            row["sewing_within_1_05"] = not over
            if over and require == "1":
                fail("sewing", "free border %.4g vs OpenCASCADE's %.4g"
                     % (row["free_border"], occt["free_length"]))
            elif over:
                notes.append("free border %.4g vs OpenCASCADE's %.4g"
                             % (row["free_border"], occt["free_length"]))
    row["note"] = "; ".join(notes)
    print(json.dumps(row))

    def cell(key, fmt):
        return fmt % row[key] if key in row else "-"
    print("%-28s %-6s %7.2f %7.1f %8s %10s %10s %8s %6s %6s  %s" % (
        name[:28], row["result"], row["build_s"], row["peak_mb"], cell("surfaces", "%d"),
        cell("free_fraction", "%.3g"), cell("occt_free_fraction", "%.3g"),
        cell("error_px", "%.3f"), cell("cracks", "%d"), cell("failed_surfaces", "%d"),
        row["note"]))


def summary(path):
    rows = [json.loads(line) for line in open(path) if line.strip()]
    failed = {}
    for r in rows:
        if r["result"] != "ok":
            failed[r.get("reason", "other")] = failed.get(r.get("reason", "other"), 0) + 1
    by_reason = ", ".join("%s %d" % (k, failed[k]) for k in sorted(failed))
    skipped = sum(r.get("skipped_faces", 0) for r in rows)
    print("%d files, %d ok, %d failed%s; %d faces skipped (named) in %d files" % (
        len(rows), len(rows) - sum(failed.values()), sum(failed.values()),
        " (%s)" % by_reason if by_reason else "", skipped,
        sum(1 for r in rows if r.get("skipped_faces"))))


if __name__ == "__main__":
    if sys.argv[1] == "summary":
        summary(sys.argv[2])
    else:
        main(sys.argv)
