#!/usr/bin/env python3
"""scripts/runout_logs.py on small hand-written logs: the paired comparison and the tables by
the balls still needed (8-ball) and by the balls left (9-ball)."""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "runout_logs.py")


def shot(layout, group, q, kind, next_shooter, over=0, foul=0, anywhere=None, exp=0.90,
         value=0.800):
    seen = f"anywhere {anywhere} " if anywhere is not None else ""
    return (f"in_hand_q 1.00 {seen}layout {layout} group_a {group} q {q:.2f} kind {kind} balls 3 "
            f"call 0/-1 speed 1.00 side 0.00 top 0.00 exp {exp:.2f} value {value:.3f} sims 10 -> "
            f"foul {foul} next {next_shooter} over {over}\n")


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


class RunoutLogs(unittest.TestCase):
    def write(self, text):
        f = tempfile.NamedTemporaryFile("w", suffix=".log", delete=False)
        f.write(text)
        f.close()
        self.addCleanup(os.unlink, f.name)
        return f.name

    def test_compare_counts_the_racks_only_one_arm_cleared(self):
        base = self.write("rack 0 1\nrack 1 0\nrack 2 0\nrack 3 1\n")
        arm = self.write("rack 0 1\nrack 1 1\nrack 2 1\nrack 3 0\nrack 9 1\n")
        r = run("compare", base, arm)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("racks 4: base 2, arm 3; only base 1, only arm 2; z 0.58", r.stdout)

    def test_needed_tables_shots_by_the_balls_left(self):
        # Player A on solids (group 0): the 1, the 2 and the 8 left, then the 2 and the 8.
        three = "0:0.5,0.5 1:1.0,0.5 2:1.5,0.5 8:2.0,0.5 9:2.0,1.0"
        two = "0:0.5,0.5 2:1.5,0.5 8:2.0,0.5 9:2.0,1.0"
        log = (shot(three, 0, 0.95, 0, 0) + shot(two, 0, 0.40, 2, 1) + "rack 0 0\n" +
               shot(three, 0, 0.99, 0, 0) + shot(two, 0, 0.95, 0, 0) +
               shot("0:0.5,0.5 8:2.0,0.5 9:2.0,1.0", 0, 0.97, 0, -1, over=1) + "rack 1 1\n")
        r = run("needed", self.write(log))
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = {line.split()[0]: line.split()[1:] for line in r.stdout.splitlines()[1:]}
        self.assertEqual(rows["3"], ["2", "100.0%", "100.0%", "0"])
        self.assertEqual(rows["2"], ["2", "50.0%", "50.0%", "1"])
        self.assertEqual(rows["1"], ["1", "100.0%", "100.0%", "0"])

    def test_left_tables_shots_by_the_object_balls_on_the_table(self):
        # 9-ball (no groups): the 8 and the 9 left with the cue ball in hand, then the 9 alone.
        two = "8:1.5,0.5 9:2.0,0.5"
        log = (shot(two, -1, 0.95, 0, 0) + shot("0:0.5,0.5 9:2.0,0.5", -1, 0.50, 0, 1) +
               "rack 0 0\n" + shot(two, -1, 0.80, 0, 0) +
               shot("0:0.5,0.5 9:2.0,0.5", -1, 0.99, 0, -1, over=1) + "rack 1 1\n")
        r = run("left", self.write(log))
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = {line.split()[0]: line.split()[1:] for line in r.stdout.splitlines()[1:]}
        self.assertEqual(rows["2"], ["2", "100.0%", "50.0%", "0"])
        self.assertEqual(rows["1"], ["2", "50.0%", "50.0%", "1"])

    def test_stuck_tables_the_share_cleared_by_the_balls_no_spot_pots(self):
        # Solids (group 0), the 1, the 2 and the 8 left. Rack 0: the 2 pottable from nowhere
        # (0.01), run lost; rack 1: every ball pottable, cleared; rack 2: the 8 unpottable,
        # cleared. The 9 (not his) is unpottable in all three and does not count.
        three = "0:0.5,0.5 1:1.0,0.5 2:1.5,0.5 8:2.0,0.5 9:2.0,1.0"
        log = (shot(three, 0, 0.9, 0, 1, anywhere="1:0.900 2:0.010 8:0.990 9:0.000") +
               "rack 0 0\n" +
               shot(three, 0, 0.9, 0, 0, anywhere="1:0.900 2:0.800 8:0.990 9:0.000") +
               "rack 1 1\n" +
               shot(three, 0, 0.9, 0, 0, anywhere="1:0.900 2:0.800 8:0.020 9:0.000") +
               "rack 2 1\n")
        r = run("stuck", self.write(log))
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = [line.split() for line in r.stdout.splitlines()[1:]]
        self.assertEqual(rows, [["3", "0", "no", "1", "100.0%"], ["3", "0", "yes", "1", "100.0%"],
                                ["3", "1", "no", "1", "0.0%"]])

    def test_ends_tables_the_last_shot_of_each_run_lost(self):
        three = "0:0.5,0.5 1:1.0,0.5 2:1.5,0.5 8:2.0,0.5 9:2.0,1.0"
        two = "0:0.5,0.5 2:1.5,0.5 8:2.0,0.5 9:2.0,1.0"
        open_table = "0:0.5,0.5 1:1.0,0.5 8:2.0,0.5 9:2.0,1.0"
        log = (shot(three, 0, 0.95, 0, 0) + shot(two, 0, 0.10, 2, 1, exp=0.40, value=0.300) +
               "rack 0 0\n" + shot(three, 0, 0.95, 0, 0) +
               shot(two, 0, 0.00, 2, 1, exp=0.60, value=0.400) + "rack 1 0\n" +
               shot(open_table, -1, 0.70, 0, 1, exp=0.70, value=0.500) + "rack 2 0\n" +
               shot(three, 0, 0.95, 0, -1, over=1) + "rack 3 1\n")
        r = run("ends", self.write(log))
        self.assertEqual(r.returncode, 0, r.stderr)
        rows = [line.split() for line in r.stdout.splitlines()[1:]]
        self.assertEqual(rows, [["2", "kick", "2", "0.05", "0.50", "0.350"],
                                ["open", "pot", "1", "0.70", "0.70", "0.500"]])

    def test_a_log_without_layouts_is_refused_with_the_fix(self):
        r = run("needed", self.write("rack 0 1\n"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("AI_VERBOSE_LAYOUT=1", r.stderr)
        r = run("stuck", self.write(shot("0:0.5,0.5 1:1.0,0.5 8:2.0,0.5", 0, 0.9, 0, 0) +
                                    "rack 0 1\n"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("AI_VERBOSE_LAYOUT=1", r.stderr)


if __name__ == "__main__":
    unittest.main()
