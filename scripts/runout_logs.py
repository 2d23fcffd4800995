#!/usr/bin/env python3
"""Reads the standard error of `ai_strength runouts --paired 1` (docs/ai.md, "Strength").

    compare BASE ARM   racks cleared by each of two arms on the same racks, the racks only one
                       cleared, and z = (only arm - only base) / sqrt(both): about one
                       standard error per unit
    needed LOG...      8-ball, with AI_VERBOSE=1 AI_VERBOSE_LAYOUT=1: by the balls the
                       shooter (player A, who runs the rack) still needs (his group's and the
                       8), the shots, the share made, the share with a pot of chance 0.9 or
                       more on, and the runs that ended there
    left LOG...        the same table by the object balls on the table (for 9-ball)
    stuck LOG...       8-ball: the share of racks cleared from each shot, by the balls still
                       needed and by how many of the shooter's group balls, and whether the
                       8, no spot of the cue ball pots (`anywhere` chance below 0.05)
    ends LOG...        how the runs that were not cleared ended: their last shot, by the
                       balls still needed (8-ball; "open" before the group is set) and its
                       kind, with the mean q, planned success and value

    AI_VERBOSE=1 AI_VERBOSE_LAYOUT=1 ai_strength runouts --game 8ball --n 300 --seed 5 \\
        --paired 1 2>arm.log
    python3 scripts/runout_logs.py compare base.log arm.log
"""

import math
import re
import sys
from collections import defaultdict

SHOT = re.compile(
    r"layout (?P<layout>.*) group_a (?P<group>-?\d+) q (?P<q>[\d.]+) kind (?P<kind>\d).*"
    r"-> foul (?P<foul>\d) next (?P<next>-?\d) over (?P<over>\d)"
)
BREAK_KIND = 3
KINDS = ("pot", "safety", "kick", "break", "push-out")
ANYWHERE = re.compile(r"anywhere (?P<anywhere>.*?) layout")
PLAN = re.compile(r"kind \d balls \d+ call \S+ speed \S+ side \S+ top \S+ "
                  r"exp (?P<exp>[\d.]+) value (?P<value>[\d.]+)")
UNPOTTABLE = 0.05  # an `anywhere` chance below this: no spot of the cue ball pots the ball


def racks(path):
    """Yields (rack index, cleared, [its shot lines]) per rack, in the order played."""
    shots = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("rack "):
                _, index, cleared = line.split()
                yield int(index), cleared == "1", shots
                shots = []
            else:
                shots.append(line)


def compare(base_path, arm_path):
    base = {i: c for i, c, _ in racks(base_path)}
    arm = {i: c for i, c, _ in racks(arm_path)}
    common = sorted(set(base) & set(arm))
    if not common:
        sys.exit("no rack is in both logs: were both run with --paired 1 and the same --seed?")
    only_base = sum(1 for i in common if base[i] and not arm[i])
    only_arm = sum(1 for i in common if arm[i] and not base[i])
    z = (only_arm - only_base) / math.sqrt(max(only_base + only_arm, 1))
    print(f"racks {len(common)}: base {sum(base[i] for i in common)}, "
          f"arm {sum(arm[i] for i in common)}; only base {only_base}, only arm {only_arm}; "
          f"z {z:.2f}")


def group_balls(group):
    """Player A's group (8-ball): the solids for group 0, the stripes for group 1."""
    return range(1, 8) if group == 0 else range(9, 16)


def needed(group, layout):
    """The balls player A still needs (8-ball), or None on an open table."""
    if group < 0:
        return None
    ids = [int(item.split(":")[0]) for item in layout.split()]
    mine = group_balls(group)
    return sum(1 for i in ids if i in mine) + 1


def balls_left(group, layout):
    """The object balls on the table (the cue ball is left out)."""
    del group
    return sum(1 for item in layout.split() if item.split(":")[0] != "0")


def shots_of(lines):
    """The shots of a rack after the break: (line, its SHOT match)."""
    out = []
    for line in lines:
        m = SHOT.search(line)
        if m and int(m["kind"]) != BREAK_KIND:
            out.append((line, m))
    return out


def by_balls(paths, key, heading):
    """Prints the table by key(group, layout) of each shot (shots without a key are skipped)."""
    shots = defaultdict(lambda: [0, 0, 0])  # shots, made, easy
    ended = defaultdict(int)
    for path in paths:
        for _, cleared, lines in racks(path):
            last = None
            for _, m in shots_of(lines):
                n = key(int(m["group"]), m["layout"])
                if n is None:
                    continue
                made = m["foul"] == "0" and (m["next"] == "0" or m["over"] == "1")
                s = shots[n]
                s[0] += 1
                s[1] += made
                s[2] += float(m["q"]) >= 0.9
                last = n
            if not cleared and last is not None:
                ended[last] += 1
    if not shots:
        sys.exit("no shot with a layout (8-ball: after the group is set): run with "
                 "AI_VERBOSE=1 AI_VERBOSE_LAYOUT=1")
    print(f"{heading:>6}  shots  made    q>=0.9  runs ended there")
    for n in sorted(shots, reverse=True):
        count, made, easy = shots[n]
        print(f"{n:6d}  {count:5d}  {made / count:6.1%}  {easy / count:6.1%}  {ended[n]:5d}")


def stuck_table(paths):
    """Prints the share cleared by (balls needed, unpottable group balls, unpottable 8)."""
    states = defaultdict(lambda: [0, 0])  # shots, from racks cleared
    for path in paths:
        for _, cleared, lines in racks(path):
            for line, m in shots_of(lines):
                group = int(m["group"])
                a = ANYWHERE.search(line)
                if group < 0 or not a:
                    continue
                chances = {int(b): float(q) for b, q in
                           (item.split(":") for item in a["anywhere"].split())}
                mine = group_balls(group)
                stuck = sum(1 for b, q in chances.items() if b in mine and q < UNPOTTABLE)
                eight = chances.get(8, 1.0) < UNPOTTABLE
                s = states[(needed(group, m["layout"]), min(stuck, 2), eight)]
                s[0] += 1
                s[1] += cleared
    if not states:
        sys.exit("no shot with a group set and `anywhere` chances: run 8-ball with "
                 "AI_VERBOSE=1 AI_VERBOSE_LAYOUT=1")
    print("needed  stuck  8 stuck  shots  cleared")
    for (n, stuck, eight) in sorted(states, key=lambda k: (-k[0], k[1], k[2])):
        count, won = states[(n, stuck, eight)]
        label = "2+" if stuck == 2 else str(stuck)
        print(f"{n:6d}  {label:>5}  {'yes' if eight else 'no':>7}  {count:5d}  {won / count:6.1%}")


def ends_table(paths):
    """Prints the last shot of every run not cleared, by balls needed and kind."""
    ends = defaultdict(list)  # (needed or "open", kind) -> [(q, exp, value)]
    for path in paths:
        for _, cleared, lines in racks(path):
            shots = shots_of(lines)
            if cleared or not shots:
                continue
            line, m = shots[-1]
            plan = PLAN.search(line)
            if not plan:
                continue
            group = int(m["group"])
            n = needed(group, m["layout"]) if group >= 0 else "open"
            ends[(n, KINDS[int(m["kind"])])].append(
                (float(m["q"]), float(plan["exp"]), float(plan["value"])))
    if not ends:
        sys.exit("no run ended on a shot with its plan: run with AI_VERBOSE=1")
    print("needed  kind      runs  mean q  exp   value")
    for key in sorted(ends, key=lambda k: (k[0] == "open", -k[0] if k[0] != "open" else 0, k[1])):
        rows = ends[key]
        q, e, v = (sum(r[i] for r in rows) / len(rows) for i in range(3))
        print(f"{key[0]:>6}  {key[1]:<8}  {len(rows):4d}  {q:6.2f}  {e:4.2f}  {v:5.3f}")


def main(argv):
    if len(argv) == 3 and argv[0] == "compare":
        compare(argv[1], argv[2])
    elif len(argv) >= 2 and argv[0] == "needed":
        by_balls(argv[1:], needed, "needed")
    elif len(argv) >= 2 and argv[0] == "left":
        by_balls(argv[1:], balls_left, "left")
    elif len(argv) >= 2 and argv[0] == "stuck":
        stuck_table(argv[1:])
    elif len(argv) >= 2 and argv[0] == "ends":
        ends_table(argv[1:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
