#!/usr/bin/env python3
"""Summarizes a `coolaaber-cli simulate` output for a human.

Reads the output document (docs/cli.md) on standard input and prints which balls were
pocketed and where, the events by type, how many object balls reached a cushion, the time to
rest, and whether the shot was truncated by the event cap.

    echo '{"rack": {"game": "8ball", "seed": 7}, "strike": {"speed": 6.7}}' |
        coolaaber-cli simulate | python3 scripts/break_summary.py
"""

import json
import sys
from collections import Counter

POCKETS = {
    "SW": "south-west corner",
    "S": "south side",
    "SE": "south-east corner",
    "NW": "north-west corner",
    "N": "north side",
    "NE": "north-east corner",
}


def ball_name(ball_id):
    return "the cue ball" if ball_id == 0 else f"ball {ball_id}"


def summarize(doc):
    events = doc.get("events", [])
    final = doc.get("final", [])
    lines = []

    pockets = [e for e in events if e.get("type") == "pocket"]
    if pockets:
        lines.append(f"Pocketed ({len(pockets)}):")
        for e in pockets:
            pocket = e.get("pocket", "?")
            where = POCKETS.get(pocket, pocket)
            for ball_id in e.get("balls", []):
                lines.append(f"  {ball_name(ball_id):>13} in {pocket:<2} ({where}) at {e['time']:.3f} s")
    else:
        lines.append("Pocketed: nothing")

    cue = next((b for b in final if b.get("id") == 0), None)
    if cue is not None:
        if cue.get("state") == "pocketed":
            lines.append(f"Cue ball: scratched in {cue.get('pocket', '?')}")
        else:
            x, y = cue["pos"]
            lines.append(f"Cue ball: ends at ({x:.3f}, {y:.3f}) m, {cue.get('state')}")

    railed = {b for e in events if e.get("type") == "cushion" for b in e.get("balls", []) if b != 0}
    lines.append(f"Object balls that reached a cushion: {len(railed)}"
                 + (f" ({', '.join(str(b) for b in sorted(railed))})" if railed else ""))

    counts = Counter(e.get("type", "?") for e in events)
    by_type = ", ".join(f"{n} {t}" for t, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))
    lines.append(f"Events: {doc.get('event_count', len(events))}" + (f" ({by_type})" if by_type else ""))

    if doc.get("truncated"):
        lines.append("Truncated: yes — the event cap was reached; final positions are those at "
                     "the last event (raise max_events to see the rest)")
    else:
        rest = doc.get("rest_time")
        lines.append(f"Time to rest: {rest:.2f} s" if rest is not None else "Time to rest: unknown")
        lines.append("Truncated: no")
    return "\n".join(lines)


def main():
    text = sys.stdin.read()
    if not text.strip():
        print("break_summary: no input (did coolaaber-cli simulate fail?)", file=sys.stderr)
        return 1
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as e:
        print(f"break_summary: the input is not JSON ({e})", file=sys.stderr)
        return 1
    if not isinstance(doc, dict) or "events" not in doc or "final" not in doc:
        print("break_summary: the input is not a simulate output (no events/final)", file=sys.stderr)
        return 1
    print(summarize(doc))
    return 0


if __name__ == "__main__":
    sys.exit(main())
