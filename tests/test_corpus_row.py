#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""tests/corpus_row.py's verdicts on made-up steps' outputs: a pack with
fewer surfaces than OpenCASCADE's faces fails unless the build named the
difference as skipped faces; a failed step keeps its reason; cracks fail
the walk; the summary counts files, ok, failed by reason and skipped faces.
  test_corpus_row.py SOURCE_DIR"""
import json
import os
import subprocess
import sys
import tempfile

src = sys.argv[1]
row_py = os.path.join(src, "tests", "corpus_row.py")
work = tempfile.mkdtemp(prefix="swcorpus_row.")
failures = 0


def put(name, obj):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        json.dump(obj, f)
    return path


def info(surfaces, skipped_faces, other_skipped=0):
    notes = [{"source": "x.step", "kind": "skipped", "what": "face #%d: trims 1 mm apart" % i,
              "count": 1} for i in range(skipped_faces)]
    if other_skipped:
        notes.append({"source": "x.step", "kind": "skipped", "what": "IGES 406",
                      "count": other_skipped})
    return put("info.json", {"parts": [{"surfaces": surfaces}], "import_notes": notes,
                             "border": {"free_length": 1.0, "length": 10.0,
                                        "free_fraction": 0.1}})


def walk(cracks):
    return put("walk.json", {"cracks_max": cracks, "seam": {"error_px_beyond_sewing_max": 0.1,
                                                            "surfaces_failed_max": 0}})


occt = put("occt.json", {"faces": 5, "free_length": 1.0, "length": 10.0})


def row(result="ok", reason="", info_p="", walk_p="", occt_p=""):
    out = subprocess.run([sys.executable, row_py, "row", "x.step", result, reason, "1000", "2048",
                          info_p, walk_p, occt_p, "1", "", ""], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    with open(os.path.join(work, "rows.jsonl"), "a") as f:
        f.write(out[0] + "\n")
    return json.loads(out[0])


def check(what, cond, got):
    global failures
    print("%s %s" % ("ok  " if cond else "FAIL", what))
    if not cond:
        print("  got %s" % got)
        failures += 1


r = row(info_p=info(3, 1), walk_p=walk(0), occt_p=occt)
check("3 surfaces for 5 faces, 1 named skipped: fails for faces",
      r["result"] == "fail" and r.get("reason") == "faces", r)
r = row(info_p=info(3, 0, other_skipped=2), walk_p=walk(0), occt_p=occt)
check("skipped entities that are not faces do not count", r.get("reason") == "faces", r)
r = row(info_p=info(3, 2), walk_p=walk(0), occt_p=occt)
check("3 surfaces for 5 faces, 2 named skipped: ok, said", r["result"] == "ok" and
      "2 faces skipped, each named" in r["note"] and r["skipped_faces"] == 2, r)
r = row(info_p=info(5, 0), walk_p=walk(0), occt_p=occt)
check("every face a surface: ok", r["result"] == "ok" and r["occt_faces"] == 5, r)
r = row(result="fail", reason="verify", info_p=info(5, 0))
check("a failed verify keeps its reason", r["result"] == "fail" and r["reason"] == "verify", r)
r = row(info_p=info(5, 0), walk_p=walk(2), occt_p=occt)
check("cracks fail the walk", r["result"] == "fail" and r["reason"] == "walk", r)
summary = subprocess.run([sys.executable, row_py, "summary", os.path.join(work, "rows.jsonl")],
                         capture_output=True, text=True, check=True).stdout.strip()
check("the summary", summary == "6 files, 2 ok, 4 failed (faces 2, verify 1, walk 1); "
      "3 faces skipped (named) in 2 files", summary)
print("%d failed" % failures)
sys.exit(1 if failures else 0)
