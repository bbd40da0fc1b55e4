#!/usr/bin/env python3
"""Tests of report.py's picture and error-budget logic on hand-made rows (expected values worked out by
hand below), and one end-to-end run on a small Google Benchmark JSON. Standard library only.

Usage: python3 benchmarks/report_test.py
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report  # noqa: E402

N = 65536


def row(ns, err, nan=0):
    return {"ns": ns, "max_rel": err, "p99_ulp": 0.0, "max_ulp": 0.0, "nan": nan, "bound": -1.0}


def point(ns, err, name):
    return {"ns": ns, "err": err, "label": name}


class ParetoFrontier(unittest.TestCase):
    def test_keeps_only_points_nothing_beats_on_both(self):
        a, b, c = point(1, 1e-2, "a"), point(2, 1e-3, "b"), point(3, 5e-3, "c")  # c: b is faster and better
        d, e = point(3, 1e-4, "d"), point(3, 1e-5, "e")  # same time: only the more accurate e
        f = point(4, 1e-5, "f")  # as accurate as e but slower: not on the frontier
        g = point(5, 0.0, "g")  # exact: the last step
        h = point(0.5, math.inf, "h")  # fastest, but unbounded (a NaN): fits no budget
        front = report.pareto_frontier([g, f, e, h, d, c, b, a])
        self.assertEqual([p["label"] for p in front], ["a", "b", "e", "g"])

    def test_a_single_point_is_its_own_frontier(self):
        self.assertEqual([p["label"] for p in report.pareto_frontier([point(7, 1e-3, "x")])], ["x"])
        self.assertEqual(report.pareto_frontier([]), [])


class PicturePoints(unittest.TestCase):
    rows = {
        ("scalar.exact.phong.float", "typical", 4, N): row(2.0, 1e-6),
        ("scalar.exact.phong.float", "stiff_a", 4, N): row(3.0, 1e-2),
        ("scalar.exact.phong.float", "stiff_b", 4, N): row(2.5, 1e-3),
        ("batch.fast.phong.float", "typical", 4, N): row(1.0, 1e-4),
        ("batch.fast.phong.float", "stiff_a", 4, N): row(1.0, 1e-3, nan=2),  # a NaN: unbounded error
        ("batch.fast.phong.float", "stiff_b", 4, N): row(0.5, 1e-3),
        ("gpu.stable.phong.float", "typical", 4, N): row(9.0, 1e-7),  # no stiff rows: typical only
        ("scalar.exact.blinn.float", "typical", 4, N): row(2.2, 1e-6),  # Blinn: not in the picture
        ("scalar.exact.phong.float", "typical", 1, N): row(5.0, 1e-6),  # K = 1: not in the picture
        ("scalar.exact.phong.double", "typical", 4, N): row(2.4, 1e-15),  # other type
        ("feature.full.float", "typical", 4, N): row(9.0, 1e-6),  # not a <path>.<mode>.<spec>.<type> row
        ("naive_glm.exact.phong.float", "typical", 4, N): row(4.0, 2e-6),
    }

    def by_label(self, sets):
        return {p["label"]: p for p in report.picture_points(self.rows, "float", sets, N)}

    def test_typical_panel_has_one_point_per_phong_variant_of_the_type(self):
        pts = self.by_label(["typical"])
        self.assertEqual(sorted(pts), ["GLM loop", "batch fast", "gpu stable", "scalar exact"])
        self.assertEqual((pts["scalar exact"]["ns"], pts["scalar exact"]["err"]), (2.0, 1e-6))
        self.assertTrue(pts["GLM loop"]["anchor"])
        self.assertFalse(pts["scalar exact"]["anchor"])

    def test_stiff_panel_takes_the_worst_error_and_time_over_the_sets(self):
        pts = self.by_label(["stiff_a", "stiff_b"])
        self.assertEqual(sorted(pts), ["batch fast", "scalar exact"])  # gpu and GLM have no stiff rows
        self.assertEqual((pts["scalar exact"]["ns"], pts["scalar exact"]["err"]), (3.0, 1e-2))
        self.assertEqual(pts["batch fast"]["err"], math.inf)
        self.assertEqual(pts["batch fast"]["nan"], 2)

    def test_budget_list_reads_the_frontier_over_all_sets(self):
        md = "\n".join(report.budget_section(self.rows, N, ["stiff_a", "stiff_b"]))
        # Over typical + stiff, float: scalar.exact (3.0 ns, 1e-2) is the only variant with every set and a
        # bounded error (batch.fast has a NaN, gpu.stable no stiff rows); 1e-2 > 1/510.
        self.assertIn("- `scalar.exact`, 3.00 ns / pair, max error 1.0e-02", md)
        self.assertIn("**above** half an 8-bit level", md)
        self.assertNotIn("- `batch.fast`", md)
        # Typical alone: batch.fast (1.0 ns, 1e-4) -> scalar.exact (2.0 ns, 1e-6) -> gpu.stable (9.0 ns, 1e-7).
        self.assertIn("`batch.fast` (1.0e-04, 1.00 ns) → `scalar.exact` (1.0e-06, 2.00 ns) → "
                      "`gpu.stable` (1.0e-07, 9.00 ns)", md)
        self.assertNotIn("`naive_glm", md.split("Anchors")[0])  # anchors are not recommended


class InterleavedSection(unittest.TestCase):
    def test_rows_with_a_target_get_its_limit_and_verdict(self):
        text = ("hand-written kernel: avx512, float, typical points, N = 65536, 60 interleaved repetitions\n"
                "phong K=16  hand 1.042 ns/pair  batch fast 0.620 ns/pair  ratio of best 0.59  median ratio 0.61\n"
                "blinn K=4   hand 1.473 ns/pair  batch exact 1.365 ns/pair  ratio of best 0.93  median ratio 0.93\n"
                "blinn K=4   hand 1.473 ns/pair  batch stable 2.917 ns/pair  ratio of best 1.98  median ratio 1.98\n")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "batch_ratio.txt")
            with open(path, "w") as f:
                f.write(text)
            md = report.interleaved_section(path)
        rows = [line for line in md if line.startswith("| ") and not line.startswith("| mode")]
        self.assertEqual(rows, ["| fast | phong | 16 | 1.042 | 0.620 | 0.61 | 0.6 | **no** |",  # 0.61 > 0.6
                                "| exact | blinn | 4 | 1.473 | 1.365 | 0.93 | 1.0 | yes |",
                                "| stable | blinn | 4 | 1.473 | 2.917 | 1.98 | – | – |"])  # no stable target at K = 4

    def test_ftz_rows_beside_the_default_ones(self):
        text = ("CPU: Some CPU\n"
                "phong K=1   hand 1.000 ns/pair  batch exact 0.800 ns/pair  ratio of best 0.80  median ratio 0.81\n"
                "phong K=1   ftz/daz  hand 0.990 ns/pair  batch exact 0.790 ns/pair  median ratio 0.80  "
                "default/ftz: batch 1.012  hand 1.004\n"
                "blinn K=16  ftz/daz  hand 0.990 ns/pair  batch stable 1.790 ns/pair  median ratio 1.80  "
                "default/ftz: batch 1.082  hand 1.000\n")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "batch_ratio.txt")
            with open(path, "w") as f:
                f.write(text)
            interleaved = report.interleaved_section(path)
            md = report.ftz_section(path)
        # The FTZ lines are not read as default-environment rows.
        self.assertEqual(len([line for line in interleaved if line.startswith("| ") and not line.startswith("| mode")]), 1)
        rows = [line for line in md if line.startswith("| ") and not line.startswith("| mode")]
        self.assertEqual(rows, ["| exact | phong | 1 | 0.81 | 0.80 | 1.012 | yes | 1.004 |",
                                "| stable | blinn | 16 | – | 1.80 | 1.082 | **no** | 1.000 |"])  # 1.082 > 1.05

    def test_no_rows_no_section(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "batch_ratio.txt")
            with open(path, "w") as f:
                f.write("phong_batch_ratio: the hand-written kernel needs AVX-512F or AVX2 + FMA\n")
            self.assertEqual(report.interleaved_section(path), [])


class EndToEnd(unittest.TestCase):
    def test_report_and_picture_from_benchmark_json(self):
        bench = []
        for name, ns, err in (("naive_glm.exact.phong.float/typical", 20.0, 4e-6),
                              ("naive_glm.exact.phong.float/stiff_x", 30.0, 3e-2),
                              ("batch.exact.phong.float/typical", 2.0, 3e-6),
                              ("batch.exact.phong.float/stiff_x", 2.5, 2e-2),
                              ("batch.newmode.phong.float/typical", 1.2, 1e-3),
                              ("batch.newmode.phong.float/stiff_x", 1.3, 5e-1),
                              ("scalar.stable.phong.float/typical", 15.0, 5.9e-8),
                              ("scalar.stable.phong.float/stiff_x", 16.0, 5.9e-8)):
            n = f"{name}/K:4/N:{N}"
            bench.append({"name": n + "_median", "run_name": n, "run_type": "aggregate", "aggregate_name": "median",
                          "ns_per_pair": ns, "max_rel_err": err, "p99_ulp": 1.0, "max_ulp": 1.0, "nan_count": 0,
                          "bound": -1.0})
        out = tempfile.mkdtemp()
        try:
            results = os.path.join(out, "results.json")
            with open(results, "w") as f:
                json.dump({"context": {}, "benchmarks": bench}, f)
            subprocess.run([sys.executable, os.path.join(os.path.dirname(__file__), "report.py"), results, out],
                           check=True)
            md = open(os.path.join(out, "report.md")).read()
            # Over typical and stiff_x: batch.newmode (1.3 ns, 5e-1), batch.exact (2.5 ns, 2e-2),
            # scalar.stable (16 ns, 5.9e-8); the GLM loop is dominated and an anchor anyway.
            frontier = [line for line in md.splitlines() if line.startswith("- `")]
            self.assertEqual([line.split("`")[1] for line in frontier],
                             ["batch.newmode", "batch.exact", "scalar.stable"])
            if shutil.which("gnuplot"):
                script = open(os.path.join(out, "error_vs_time.gp")).read()
                self.assertIn("'batch newmode'", script)  # a mode the code does not know, labelled
                self.assertIn("'GLM loop'", script)
                self.assertTrue(os.path.getsize(os.path.join(out, "error_vs_time.png")) > 10000)
        finally:
            shutil.rmtree(out)


if __name__ == "__main__":
    unittest.main()
