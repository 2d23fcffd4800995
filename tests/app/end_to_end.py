#!/usr/bin/env python3
"""End-to-end tests of the real game under a virtual display (run by ctest through xvfb-run -a).

The real `coolaaber` window is driven with xdotool (the real mouse), screenshots are taken with
ImageMagick's `import`, and the game's --status-file test hook says what the player sees (the
information bar, whose turn, whether the balls move, where the panel's buttons are).

  end_to_end.py controls COOLAABER WORKDIR   aim with a right-drag and strike on release, wait
      for the balls to stop, Change View, the Sound checkbox, Restart (confirmed), Exit (status 0)
  end_to_end.py game COOLAABER WORKDIR       a whole game between two scripted players (the test
      hook --players random,random) ends with the winner in the information bar
  end_to_end.py hinted COOLAABER WORKDIR     a human plays a whole game against the AI: Hint,
      then a right click to strike, every turn (needs a build with src/ai)
  end_to_end.py snooker COOLAABER WORKDIR    a snooker frame from New Game: a stroke, the
      scoreboard and the words, the after-foul choice, both views
  end_to_end.py three_cushion COOLAABER WORKDIR   a three-cushion game from New Game: a stroke,
      its words, the innings, both views
  end_to_end.py practice_tables COOLAABER WORKDIR   practice on the snooker table from New Game:
      a red dragged, a stroke, Try again, Save and Load position; then the three-cushion table;
      both views of each
"""
import base64
import json
import os
import shutil
import subprocess
import sys
import time


# A saved 8-ball game (the session format of docs/game.md), Player 1 to shoot, with the balls at
# `balls` ({id: (x, y)}; 0 the cue ball unless it is in hand); the others count as pocketed.
def saved_game(balls, cue_ball="on_table", shot="normal"):
    table = {"length": 2.54, "width": 1.27, "corner_mouth": 0.116, "side_mouth": 0.1285,
             "corner_facing_deg": 142.0, "side_facing_deg": 104.0, "jaw_nose_radius": 0.005,
             "cushion_height": 0.03629, "corner_shelf": 0.0286, "side_shelf": 0.0048, "jaw_depth": 0.0635,
             "pockets": True}
    params = {"ball_radius": 0.028575, "ball_mass": 0.17, "gravity": 9.81, "mu_slide": 0.2, "mu_roll": 0.01,
              "spin_decel": 10.9, "e_ball": 0.95, "mu_ball": None, "e_cushion": 0.85, "mu_cushion": 0.2,
              "cue_mass": 0.567, "cue_tip_e": 0.75, "cue_endmass": 0.015, "miscue_limit": 0.5}
    options = {"call_shots": "all", "eight_on_break": "spot_or_rebreak", "foul_ball_in_hand": "anywhere",
               "scratch_on_eight_loses": False, "groups_on_break": False, "rail_after_contact": True}
    config = {"game": "8ball", "options": options, "table": table, "params": params,
              "players": {"A": "Player 1", "B": "Player 2"}, "seed": 1, "first_breaker": "A", "keep_events": False}
    state = {"shooter": "A", "breaker": "A", "shot": shot, "groups": None,
             "on_table": sorted(b for b in balls if b != 0), "cue_ball": cue_ball, "call": None,
             "fouls_in_row": {"A": 0, "B": 0}, "warned": {"A": False, "B": False},
             "positions": {str(b): list(p) for b, p in sorted(balls.items())}}
    pocketed = [{"ball": b, "pocket": "SW", "by": "A"} for b in range(1, 16) if b not in balls]
    return {"format": "coolaaber-session", "version": 1, "config": config, "game_number": 0, "rack_number": 0,
            "score": {"A": 0, "B": 0}, "state": state, "pending": None, "winner": None, "pocketed": pocketed,
            "history": []}


class Game:
    def __init__(self, exe, work, *args, settings=None, save=None):
        self.work = work
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        if settings is not None:
            os.makedirs(os.path.join(work, "config", "coolaaber"))
            with open(os.path.join(work, "config", "coolaaber", "settings.json"), "w") as f:
                json.dump(dict({"format": "coolaaber-settings", "version": 1}, **settings), f)
        if save is not None:
            with open(os.path.join(work, "save.json"), "w") as f:
                json.dump(save, f)
            args = ("--load", os.path.join(work, "save.json"), *args)
        self.status_path = os.path.join(work, "status.json")
        env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
                   XDG_DATA_HOME=os.path.join(work, "data"), ALSOFT_DRIVERS="null")
        self.stderr = open(os.path.join(work, "stderr.txt"), "w")
        self.proc = subprocess.Popen([exe, "--size", "1280x720", "--status-file", self.status_path, *args],
                                     env=env, stderr=self.stderr)
        self.status = self.wait(lambda s: True, 30, "the first frame")
        out = subprocess.run(["xdotool", "search", "--sync", "--name", "^Coolaaber$"], capture_output=True,
                             text=True, timeout=30)
        self.window = out.stdout.split()[0]
        self.shots = 0

    def read(self):
        try:
            with open(self.status_path) as f:
                return json.load(f)
        except (OSError, ValueError):
            return None

    def wait(self, pred, timeout, what):
        end = time.time() + timeout
        while time.time() < end:
            if self.proc.poll() is not None:
                raise AssertionError(f"the game exited ({self.proc.returncode}) while waiting for {what}")
            s = self.read()
            if s is not None and pred(s):
                self.status = s
                return s
            time.sleep(0.1)
        raise AssertionError(f"timed out after {timeout} s waiting for {what}; last status: {self.read()}")

    def xdo(self, *args):
        subprocess.run(["xdotool", *args], check=True, timeout=30)

    def move(self, x, y):
        self.xdo("mousemove", "--window", self.window, str(int(x)), str(int(y)))

    def click_widget(self, label):
        # A new popup lays itself out over its first frames: wait until the widget stays put.
        w, end = None, time.time() + 10
        while time.time() < end:
            seen = self.wait(lambda s: label in s["widgets"], 10, f"the widget {label!r}")["widgets"][label]
            if seen == w:
                break
            w = seen
            time.sleep(0.3)
        self.move((w[0] + w[2]) / 2, (w[1] + w[3]) / 2)
        time.sleep(0.15)
        self.xdo("click", "--window", self.window, "1")
        time.sleep(0.3)

    def screenshot(self, name):
        path = os.path.join(self.work, name)
        subprocess.run(["import", "-window", "root", path], check=True, timeout=30)
        return path

    def close(self):
        if self.proc.poll() is None:
            self.proc.kill()
        self.stderr.close()


def differing_pixels(a, b, crop="960x720+0+0"):
    """Pixels of the table view (left of the panel) that differ by more than 8 %."""
    out = subprocess.run(["compare", "-metric", "AE", "-fuzz", "8%", a + f"[{crop}]", b + f"[{crop}]", "null:"],
                         capture_output=True, text=True, timeout=60)
    return int(float(out.stderr.split()[0]))


def check(cond, message):
    if not cond:
        raise AssertionError(message)
    print("ok:", message)


def controls(exe, work):
    g = Game(exe, work, "--seed", "3", "--game", "8ball")
    try:
        s = g.wait(lambda s: s["phase"] == "shoot" and not s["busy"], 30, "the break")
        check(s["info"][0] == "Player 1 to break", "the information bar says who breaks")
        rack = g.screenshot("1-rack.png")
        heading0 = s["heading_deg"]
        # Hold the right button and move horizontally: the aim turns; release: the strike.
        g.move(480, 400)
        time.sleep(0.2)
        g.xdo("mousedown", "--window", g.window, "3")
        for x in range(484, 521, 4):
            g.move(x, 400)
            time.sleep(0.03)
        s = g.wait(lambda s: s["shots"] == 0 and abs(s["heading_deg"] - heading0) > 1.0, 10, "the aim to turn")
        check(s["heading_deg"] < heading0, f"moving right turns the aim right ({heading0} -> {s['heading_deg']} deg)")
        g.xdo("mouseup", "--window", g.window, "3")
        s = g.wait(lambda s: s["shots"] == 1, 10, "the strike on release")
        check(True, "releasing the right button strikes")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the balls to stop")
        check(s["last_shot"].startswith("Player 1 broke"), f"the information bar reports the break: {s['last_shot']!r}")
        broken = g.screenshot("2-after-break.png")
        moved = differing_pixels(rack, broken)
        check(moved > 2000, f"the table changed from the rack ({moved} pixels)")

        # The left button aims without striking.
        heading1 = s["heading_deg"]
        g.move(480, 300)
        time.sleep(0.2)
        g.xdo("mousedown", "--window", g.window, "1")
        for x in range(470, 439, -5):
            g.move(x, 300)
            time.sleep(0.03)
        g.xdo("mouseup", "--window", g.window, "1")
        s = g.wait(lambda s: abs(s["heading_deg"] - heading1) > 1.0, 10, "the left-drag aim")
        time.sleep(0.5)
        check(g.read()["shots"] == 1, f"a left-drag aims ({heading1} -> {s['heading_deg']} deg) without striking")

        overhead = g.screenshot("3-overhead.png")
        g.click_widget("Change View")
        g.wait(lambda s: s["view"] == "cueball", 10, "the cue-ball view")
        time.sleep(2.5)  # the camera glides over
        cueview = g.screenshot("4-cue-ball-view.png")
        changed = differing_pixels(overhead, cueview)
        check(changed > 20000, f"Change View changes the image ({changed} pixels)")
        g.click_widget("Change View")
        g.wait(lambda s: s["view"] == "overhead", 10, "the overhead view again")

        g.click_widget("Sound")
        g.wait(lambda s: s["sound"] is False, 10, "the sound off")
        check(True, "the Sound checkbox turns the sound off")
        settings = os.path.join(work, "config", "coolaaber", "settings.json")
        end = time.time() + 10
        while time.time() < end and not (os.path.exists(settings) and json.load(open(settings))["sound"] is False):
            time.sleep(0.1)
        check(json.load(open(settings))["sound"] is False, "the setting is saved at once")
        g.click_widget("Sound")
        g.wait(lambda s: s["sound"] is True, 10, "the sound on")
        check(True, "and on again")

        g.click_widget("Restart")
        g.click_widget("Yes, restart")
        s = g.wait(lambda s: s["game_number"] == 1 and s["shots"] == 0, 10, "the new rack")
        check(s["balls_on_table"] == 15 and s["info"][0].endswith("to break"), "Restart racks the balls again")
        racked = g.screenshot("5-restarted.png")
        check(differing_pixels(broken, racked) > 2000, "the restarted table is not the broken one")

        g.click_widget("Exit")
        code = g.proc.wait(timeout=30)
        check(code == 0, "Exit ends the game with status 0")
        check(os.path.exists(os.path.join(work, "config", "coolaaber", "settings.json")), "the settings were saved")
    finally:
        g.close()


def whole_game(exe, work):
    g = Game(exe, work, "--seed", "11", "--game", "8ball", "--players", "random,random", "--playback-speed", "0")
    try:
        s = g.wait(lambda s: s["winner"] is not None, 300, "the end of the game")
        check(s["phase"] == "game_over", "the game is over")
        check(s["info"][0] == f"{s['winner']} wins!", f"the information bar shows the winner: {s['info'][0]!r}")
        check(s["shots"] > 0, f"after {s['shots']} shots")
        g.screenshot("game-over.png")
        g.click_widget("Exit")
        check(g.proc.wait(timeout=30) == 0, "Exit ends the game with status 0")
        check(not os.path.exists(os.path.join(work, "data", "coolaaber", "saved-game.json")),
              "a finished game is not saved for resuming")
    finally:
        g.close()


def hinted_game(exe, work):
    """A human plays a whole 9-ball game against the AI with the real mouse: on each turn he
    asks for a Hint, then strikes with a right click (press and release)."""
    g = Game(exe, work, "--seed", "8", "--game", "9ball", "--players", "human,ai:1", "--playback-speed", "4")
    try:
        strikes = 0
        while True:
            s = g.wait(lambda s: not s["busy"] and (s["winner"] or s["to_act"] == "Player 1"), 120, "my turn")
            if s["winner"]:
                break
            if s["phase"] == "choose":
                options = [k for k in s["widgets"] if k in ("Shoot from here", "Pass the shot back")]
                g.click_widget(options[0])
                continue
            before = s["shots"]
            g.click_widget("Hint")
            s = g.wait(lambda s: not s["busy"] and s["drawn"]["cue"], 60, "the hint")
            g.move(400, 660)
            time.sleep(0.2)
            g.xdo("mousedown", "--window", g.window, "3")
            time.sleep(0.1)
            g.xdo("mouseup", "--window", g.window, "3")
            g.wait(lambda s: s["shots"] > before, 20, "the strike")
            strikes += 1
            if strikes > 60:
                raise AssertionError("the game did not end in 60 of my shots")
        check(s["info"][0] == f"{s['winner']} wins!", f"a game against the AI ends: {s['info'][0]!r} after {s['shots']} shots")
        g.screenshot("hinted-game-over.png")
    finally:
        g.close()


def no_display(exe, work):
    """Without a usable display the game says so in one line and exits 1 at once."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    base = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
                XDG_DATA_HOME=os.path.join(work, "data"), ALSOFT_DRIVERS="null")
    base.pop("SDL_VIDEODRIVER", None)
    unset = {k: v for k, v in base.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    cases = [("a display no server answers", dict(unset, DISPLAY=":77"), "cannot open a window on display :77: "),
             ("an X server that refuses this user", dict(base, XAUTHORITY="/nonexistent"),
              f"cannot open a window on display {os.environ.get('DISPLAY')}: "),
             ("no display at all", unset, "cannot open a window: no display")]
    for what, env, expected in cases:
        start = time.time()
        p = subprocess.run([exe, "--players", "ai:1,ai:1"], env=env, capture_output=True, text=True, timeout=20)
        lines = p.stderr.splitlines()
        check(p.returncode == 1 and time.time() - start < 5, f"{what}: exit 1 at once ({p.returncode})")
        check(len(lines) == 1 and lines[0].startswith("coolaaber: " + expected),
              f"{what}: one clear line: {p.stderr.strip()!r}")
    check(not os.path.exists(os.path.join(work, "data", "coolaaber", "saved-game.json")), "no game was played unseen")


def key(g, name, times=1):
    g.xdo("key", "--window", g.window, "--repeat", str(times), "--delay", "8", name)


def no_choice_after_scratch(exe, work):
    """A scratch on a legal 8-ball break: the options would lead to the same position, so the
    opponent is asked nothing and has ball in hand in the kitchen."""
    save = saved_game({0: (0.45, 0.45), 1: (0.15, 0.15), 2: (2.0, 0.3), 8: (2.0, 0.6), 12: (2.0, 0.9)},
                      cue_ball="in_hand_kitchen", shot="break")
    g = Game(exe, work, settings={"power": 0.1}, save=save)
    try:
        s = g.wait(lambda s: s["phase"] == "shoot" and not s["busy"], 30, "the break")
        turn_to(g, heading_to(s["cue_ball"], (0.15, 0.15)))
        key(g, "space")
        s = g.wait(lambda s: s["shots"] == 1 and not s["moving"] and not s["busy"], 30, "the balls to stop")
        check("pocketed the 1" in s["last_shot"] and "cue ball went into a pocket" in s["last_shot"],
              f"the 1 and the cue ball dropped: {s['last_shot']!r}")
        check(s["phase"] != "choose" and s["to_act"] == "Player 2", f"Player 2 is asked nothing ({s['phase']})")
        check(not any(k in s["widgets"] for k in ("Play the table as it lies", "Ball in hand in the kitchen")),
              "no choice buttons")
        check("Ball in hand: drag the cue ball behind the head string" in s["info"], f"info: {s['info']}")
        g.screenshot("after-scratch.png")
    finally:
        g.close()


def turn_to(g, heading):
    """Turns the aim to `heading` (deg) with the arrow keys: 0.5 deg a press, then 0.05 deg with
    Shift."""
    def off():
        return (heading - g.read()["heading_deg"] + 180) % 360 - 180
    for step, mod in ((0.5, ""), (0.05, "shift+")):
        delta = off()
        if round(abs(delta) / step) > 0:
            key(g, mod + ("Left" if delta > 0 else "Right"), round(abs(delta) / step))
            time.sleep(0.3)
    return g.wait(lambda s: abs((s["heading_deg"] - heading + 180) % 360 - 180) < 0.03, 10, f"the aim at {heading}")


def heading_to(a, b):
    import math
    return math.degrees(math.atan2(b[1] - a[1], b[0] - a[0]))


def kitchen_foul(exe, work):
    """Ball in hand in the kitchen: the 3 lies in the kitchen. The aim starts elsewhere; aimed at
    the 3, the guide turns red, nothing is called and the panel says why, before the strike."""
    save = saved_game({3: (0.3, 0.9), 1: (1.5, 0.4), 8: (2.0, 0.6), 12: (1.8, 1.0)}, cue_ball="in_hand_kitchen")
    g = Game(exe, work, save=save)
    try:
        s = g.wait(lambda s: s["phase"] == "shoot" and not s["busy"] and s["cue_ball"], 30, "ball in hand")
        check(s["aim_foul"] == "" and not s["drawn"]["aim_illegal"], "the first aim is a legal one")
        g.screenshot("kitchen-legal.png")
        s = turn_to(g, heading_to(s["cue_ball"], (0.3, 0.9)))
        s = g.wait(lambda s: s["drawn"]["aim_illegal"], 10, "the red guide")
        check(s["aim_foul"].startswith("Foul as aimed: the 3 lies in the kitchen"), f"the reason: {s['aim_foul']!r}")
        check(s["call"] is None and "Call: none (click a ball, then a pocket)" in s["info"], "nothing is called")
        g.screenshot("kitchen-foul.png")
    finally:
        g.close()


def guide_marks(exe, work):
    """The practice guide straight into the NE pocket: the call (the 5 in the NE corner) and the
    path's end in the pocket are marked; the guide level is picked in the panel and persists."""
    obj, cue = (2.04, 0.77), (1.6, 0.33)  # on the diagonal into the NE corner
    g = Game(exe, work, settings={"aim_guide": "practice", "power": 0.2},
             save=saved_game({0: cue, 5: obj, 8: (0.5, 0.3)}))
    try:
        s = g.wait(lambda s: s["phase"] == "shoot" and not s["busy"], 30, "the shot")
        s = turn_to(g, heading_to(cue, obj))
        s = g.wait(lambda s: s["call"] is not None, 10, "the call")
        check(s["call"] == {"ball": 5, "pocket": 5} and s["guide_end"] == "pocket",
              f"the 5 is called in the NE corner, where the guide drops it ({s['call']}, {s['guide_end']})")
        check(s["drawn"]["marks"] == 3, f"the called ball, pocket and the path's end are marked ({s['drawn']['marks']})")
        practice = g.screenshot("guide-practice.png")
        g.click_widget("Aim guide level")
        g.click_widget("Off")
        s = g.wait(lambda s: s["aim_guide_level"] == "off", 10, "the guide off")
        check(s["drawn"]["marks"] == 2, "with the guide off the call is still marked")
        off = g.screenshot("guide-off.png")
        check(differing_pixels(practice, off) > 200, "the guide is gone from the table")
        settings = json.load(open(os.path.join(work, "config", "coolaaber", "settings.json")))
        check(settings["aim_guide"] == "off", "the level is saved")
    finally:
        g.close()


def resize(exe, work):
    """The panel is laid out for the window: every control stays in view and the table keeps
    most of the width, from 1280x720 down to 640x480; the Controls help fits too; in a tall
    window the panel goes below the table."""
    g = Game(exe, work, "--game", "8ball", "--seed", "2")
    controls = ["Sound", "Change View", "Restart", "Exit", "Aim guide level", "Strike", "Hint", "New Game...",
                "Controls"]
    try:
        for w, h in ((1280, 720), (800, 600), (640, 480), (1280, 720)):
            g.xdo("windowsize", "--sync", g.window, str(w), str(h))
            s = g.wait(lambda s: s["window"] == [w, h] and all(k in s["widgets"] for k in controls), 10,
                       f"the window at {w}x{h}")
            time.sleep(0.3)
            s = g.wait(lambda s: True, 1, "the status")
            inside = [k for k in controls
                      if 0 <= s["widgets"][k][0] and s["widgets"][k][2] <= w and 0 <= s["widgets"][k][1]
                      and s["widgets"][k][3] <= h]
            check(inside == controls, f"{w}x{h}: every control in view ({sorted(set(controls) - set(inside))} not)")
            check(s["panel_width"] <= 0.4 * w and (w < 1280 or s["panel_width"] == 300),
                  f"{w}x{h}: the panel is {s['panel_width']} px, the table {w - s['panel_width']} px")
            g.screenshot(f"window-{w}x{h}.png")
            if w == 640:
                g.click_widget("Controls")
                c = g.wait(lambda s: "Close" in s["widgets"], 10, "the Controls help")["widgets"]["Close"]
                check(c[3] <= h, f"the Controls help fits in a {w}x{h} window (its Close at y {c[3]})")
                g.screenshot("controls-help.png")
                key(g, "space")
                time.sleep(0.5)
                check(g.read()["shots"] == 0 and not g.read()["moving"], "Space does not strike while a dialog is open")
                g.click_widget("Close")
                g.wait(lambda s: "Close" not in s["widgets"], 10, "the help closed")
        # A tall window: the panel below the table, full width, its foot in view.
        w, h = 560, 700
        g.xdo("windowsize", "--sync", g.window, str(w), str(h))
        s = g.wait(lambda s: s["window"] == [w, h] and "Strike" in s["widgets"], 10, f"the window at {w}x{h}")
        time.sleep(0.3)
        s = g.wait(lambda s: True, 1, "the status")
        check(s["panel_width"] == w and s["table_view"] == [w, h - s["panel_height"]] and s["panel_height"] < h / 2,
              f"{w}x{h}: the panel below the table ({s['panel_height']} px), the table above ({s['table_view']})")
        foot = ["Strike", "Hint", "Change View"]
        inside = [k for k in foot if s["widgets"][k][1] >= h - s["panel_height"] and s["widgets"][k][3] <= h]
        check(inside == foot, f"{w}x{h}: Strike, Hint and Change View in view under the table")
        g.screenshot(f"window-{w}x{h}.png")
    finally:
        g.close()


def shot_link_text(save, stroke):
    """A shot link (docs/game.md, "Shot links") of a saved game's position and a stroke, made
    here from the format's description so that the game's reading is checked against it."""
    c = save["config"]
    shot = {"game": c["game"], "options": c["options"], "table": c["table"], "params": c["params"],
            "state": save["state"], "stroke": stroke}
    text = json.dumps(shot, separators=(",", ":")).encode()
    h = 2166136261
    for b in text:
        h = ((h ^ b) * 16777619) & 0xFFFFFFFF
    return f"shot=1.{h:08x}." + base64.urlsafe_b64encode(text).decode().rstrip("=")


def simulated_rest(save, stroke):
    """Where `coolaaber-cli simulate` leaves the balls of `save` after `stroke`: {id: [x, y]}."""
    c = save["config"]
    doc = {"table": c["table"], "params": {k: v for k, v in c["params"].items() if v is not None},
           "balls": [{"id": int(b), "pos": p} for b, p in save["state"]["positions"].items()],
           "strike": stroke}
    out = subprocess.run([os.environ["COOLAABER_CLI"], "simulate"], input=json.dumps(doc), capture_output=True,
                         text=True, timeout=60, check=True)
    return {str(b["id"]): b["pos"] for b in json.loads(out.stdout)["final"] if b["pos"] is not None}


def hold_clipboard(text):
    """A helper process that owns the X clipboard with `text` for 30 s (the game pastes from it)."""
    code = ("import sys, tkinter; r = tkinter.Tk(); r.withdraw(); r.clipboard_clear(); "
            "r.clipboard_append(sys.argv[1]); r.update(); r.after(30000, r.destroy); r.mainloop()")
    p = subprocess.Popen([sys.executable, "-c", code, text])
    time.sleep(1.0)
    return p


def shared_shot(exe, work):
    """--shot LINK sets up the link's position and plays its stroke to where the engine puts the
    balls; Replay shows it again; Copy shot link and Ctrl+V open it again; a bad link is refused
    with one line (exit 2 on the command line, the information bar for a paste)."""
    save = saved_game({0: (0.7, 0.5), 1: (1.6, 0.55), 8: (2.0, 0.9), 12: (0.4, 1.0)})
    stroke = {"speed": 2.2, "heading_deg": 3.0, "side": 0.2, "top": -0.1, "elevation_deg": 0.0}
    link, expected = shot_link_text(save, stroke), simulated_rest(save, stroke)
    check(expected != {k: v for k, v in save["state"]["positions"].items()}, "the stroke moves the balls")
    g = Game(exe, work, "--shot", link)
    try:
        s = g.wait(lambda s: s["shots"] == 1 and not s["moving"] and not s["busy"], 60, "the shared shot")
        check(s["positions"] == expected, f"the balls rest where simulate puts them: {s['positions']}")
        check("Opened a shot link" in s["link_note"], f"the information bar says so: {s['link_note']!r}")
        g.screenshot("shot-played.png")
        key(g, "p")
        g.wait(lambda s: s["replaying"], 10, "the replay")
        time.sleep(0.4)
        g.screenshot("shot-replay.png")
        s = g.wait(lambda s: not s["moving"] and not s["replaying"], 60, "the replay's end")
        check(s["positions"] == expected and s["shots"] == 1, "the replay changes nothing")
        g.click_widget("Copy shot link")
        s = g.wait(lambda s: "Copied the link of the last shot" in s["link_note"], 10, "the copy")
        g.screenshot("shot-copied.png")
        key(g, "ctrl+v")
        s = g.wait(lambda s: "Opened the pasted shot link" in s["link_note"], 20, "the paste")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the pasted shot")
        check(s["positions"] == expected and s["shots"] == 1, "the copied link of the shot is that shot")
        holder = hold_clipboard(link[:-6])
        try:
            key(g, "ctrl+v")
            s = g.wait(lambda s: "not a shot link this game can open" in s["link_note"], 20, "the bad paste")
        finally:
            holder.kill()
        check("checksum" in s["link_note"] and s["positions"] == expected and s["shots"] == 1,
              f"a bad paste is refused and the game is untouched: {s['link_note']!r}")
        g.screenshot("shot-bad-paste.png")
    finally:
        g.close()
    p = subprocess.run([exe, "--shot", link[:-6]], capture_output=True, text=True, timeout=20,
                       env=dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
                                XDG_DATA_HOME=os.path.join(work, "data")))
    lines = p.stderr.splitlines()
    check(p.returncode == 2 and len(lines) == 1 and lines[0].startswith("error: link: ") and "checksum" in lines[0],
          f"a cut link on the command line: exit 2, one line ({p.returncode}, {p.stderr.strip()!r})")


def drag(g, frm, to, steps=8):
    g.move(*frm)
    time.sleep(0.15)
    g.xdo("mousedown", "--window", g.window, "1")
    for i in range(1, steps + 1):
        g.move(frm[0] + (to[0] - frm[0]) * i / steps, frm[1] + (to[1] - frm[1]) * i / steps)
        time.sleep(0.05)
    g.xdo("mouseup", "--window", g.window, "1")
    time.sleep(0.3)


def saved_position(work, before, speed):
    """Save position's file: it holds the position `before` exactly, and `coolaaber-cli simulate`
    plays a stroke of `speed` (m/s) on it. Returns the file's JSON."""
    with open(os.path.join(work, "data", "coolaaber", "practice-position.json")) as f:
        saved = json.load(f)
    check({str(b["id"]): b["pos"] for b in saved["balls"]} == before, "the file holds the position exactly")
    out = subprocess.run([os.environ["COOLAABER_CLI"], "simulate"],
                         input=json.dumps(dict(saved, strike={"speed": speed, "heading_deg": 0.0})),
                         capture_output=True, text=True, timeout=60)
    check(out.returncode == 0 and "final" in json.loads(out.stdout), f"coolaaber-cli simulate reads it ({out.stderr.strip()!r})")
    return saved


def practice(exe, work):
    """--practice: a ball dragged to a free spot moves there, onto another ball it stays put with
    the reason; a shot plays; Try again puts back the position exactly; Save position writes what
    coolaaber-cli simulate reads; Load position brings it back."""
    g = Game(exe, work, "--practice", "--game", "9ball", "--view", "overhead", "--seed", "4")
    try:
        s = g.wait(lambda s: s["practice"] and not s["busy"], 30, "practice")
        check(s["balls_on_table"] == 9 and s["info"][0].startswith("Practice"), f"a 9-ball rack to practise on: {s['info']}")
        g.screenshot("practice-start.png")
        five = s["ball_px"]["5"]
        drag(g, five, (five[0] - 200, five[1] + 60))
        s = g.wait(lambda s: s["positions"]["5"] != g.status["positions"]["5"], 10, "the 5 moved")
        moved = s["ball_px"]["5"]
        check(abs(moved[0] - (five[0] - 200)) < 3 and abs(moved[1] - (five[1] + 60)) < 3,
              f"the 5 lies where it was dropped ({moved} for {(five[0] - 200, five[1] + 60)})")
        cue = s["ball_px"]["0"]
        drag(g, moved, cue)
        s = g.wait(lambda s: "on top of the cue ball" in s["refusal"], 10, "the refusal")
        check(s["positions"]["5"] != s["positions"]["0"], f"the 5 stays off the cue ball: {s['refusal']!r}")
        g.screenshot("practice-dragged.png")
        before = s["positions"]
        key(g, "space")
        g.wait(lambda s: s["moving"], 10, "the shot")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the balls to stop")
        check(s["positions"] != before, f"the shot moved the balls ({s['last_shot']!r})")
        g.screenshot("practice-shot.png")
        g.click_widget("Try again")
        s = g.wait(lambda s: s["positions"] == before, 10, "the position before the shot")
        check(True, "Try again puts back the position before the shot, every number")
        g.click_widget("Save position")
        s = g.wait(lambda s: "Saved the position" in s["link_note"], 10, "the save")
        saved_position(work, before, 2.0)
        nine = s["ball_px"]["9"]
        drag(g, nine, (nine[0] + 120, nine[1] - 50))
        s = g.wait(lambda s: s["positions"] != before, 10, "the 9 moved")
        g.click_widget("Load position")
        s = g.wait(lambda s: "Loaded the position" in s["link_note"], 10, "the load")
        check(s["positions"] == before, "Load position brings the saved position back")
        g.screenshot("practice-loaded.png")
    finally:
        g.close()


def start_from_new_game(g, game):
    """New Game..., pick `game` (its radio button's label), Start; waits for the first turn."""
    g.wait(lambda s: not s["busy"] and s["frames"] >= 4, 30, "the first frames")
    g.click_widget("New Game...")
    g.click_widget(game)
    g.click_widget("Start")
    return g.wait(lambda s: s["match"] is not None and s["phase"] == "shoot" and not s["busy"], 30, game)


def snooker(exe, work):
    """Snooker from New Game: the cue ball in hand in the D, a red on, 147 remaining; a stroke
    scores or fouls and the scoreboard and the words agree; after a foul the incoming player's
    choice is offered as buttons and taken; both views drawn."""
    import re
    g = Game(exe, work, "--view", "overhead", "--seed", "2")
    try:
        s = start_from_new_game(g, "Snooker")
        m = s["match"]
        check(m["game"] == "snooker" and m["in_hand"] and m["scores"] == [0, 0] and m["remaining"] == 147,
              f"a frame set up, the cue ball in hand: {m}")
        check(s["info"][0] == "Player 1 to play — on: a red", f"the information bar: {s['info']}")
        check(s["info"][1] == "Ball in hand: place the cue ball in the D", f"in the D: {s['info']}")
        time.sleep(0.5)
        g.screenshot("snooker-1-setup.png")
        key(g, "space")
        g.wait(lambda s: s["moving"], 10, "the stroke")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the balls to stop")
        m, words = s["match"], s["last_shot"]
        foul = re.match(r"Foul: (\d) points to Player 2 — ", words)
        pot = re.match(r"Player 1 pots (.*): (\d) points?, break (\d+)\.", words)
        check(foul or pot or words.startswith("No score for Player 1."), f"the stroke in words: {words!r}")
        if foul:
            check(m["scores"] == [0, int(foul.group(1))] and m["choices"] >= 2,
                  f"the foul's points are Player 2's ({m}) and he chooses")
            check("Foul by Player 1: Player 2 chooses" == s["info"][0], f"info: {s['info']}")
            g.screenshot("snooker-2-foul.png")
            g.click_widget("Ask Player 1 to play again")
            s = g.wait(lambda s: s["match"]["choices"] == 0 and not s["busy"], 10, "the choice taken")
            check(s["to_act"] == "Player 1" and s["last_shot"] == "Player 2 asks Player 1 to play again.",
                  f"Player 1 plays again: {s['last_shot']!r}")
        elif pot:
            check(m["scores"][0] == int(pot.group(2)) == m["break"], f"the scoreboard: {m}")
        board = f"Player 1 {m['scores'][0]} – {m['scores'][1]} Player 2 · break {m['break']} · {m['remaining']} remaining"
        check(board in s["info"], f"the scores in the information bar: {s['info']}")
        overhead = g.screenshot("snooker-3-overhead.png")
        g.click_widget("Change View")
        g.wait(lambda s: s["view"] == "cueball", 10, "the cue-ball view")
        time.sleep(2.5)
        cueview = g.screenshot("snooker-4-cue-ball-view.png")
        check(differing_pixels(overhead, cueview) > 20000, "the cue-ball view shows the table from the cue ball")
    finally:
        g.close()


def three_cushion(exe, work):
    """Three-cushion from New Game: the white opens at the red; a stroke's words say what it
    did (point, or no point and why) and the scoreboard's innings follow; Copy shot link and
    Ctrl+V play the same stroke again to the same game; both views drawn."""
    g = Game(exe, work, "--view", "overhead", "--seed", "2")
    try:
        s = start_from_new_game(g, "Three-cushion")
        m = s["match"]
        check(m["game"] == "three_cushion" and m["cue_ball"] == 0 and m["innings"] == [1, 0],
              f"Player 1 opens with the white: {m}")
        check(s["info"][0] == "Player 1 to play the white — inning 1", f"info: {s['info']}")
        time.sleep(0.5)
        g.screenshot("carom-1-start.png")
        key(g, "space")
        g.wait(lambda s: s["moving"], 10, "the stroke")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the balls to stop")
        m, words = s["match"], s["last_shot"]
        if words.startswith("Point:"):
            check(m["scores"] == [1, 0] and s["to_act"] == "Player 1", f"a point, Player 1 goes on: {m}")
        else:
            check(words.startswith("No point:") or words.startswith("Foul:"), f"the stroke in words: {words!r}")
            check(m["scores"] == [0, 0] and m["innings"] == [1, 1] and m["cue_ball"] == 1,
                  f"the inning passes to Player 2 and the yellow: {m}")
            check(s["info"][0] == "Player 2 to play the yellow — inning 1", f"info: {s['info']}")
        after = (s["positions"], m["scores"], m["innings"])
        g.click_widget("Copy shot link")
        g.wait(lambda s: "Copied the link of the last shot (3 balls)" in s["link_note"], 10, "the copy")
        key(g, "ctrl+v")
        g.wait(lambda s: "Opened the pasted shot link" in s["link_note"], 20, "the paste")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the pasted shot")
        check((s["positions"], s["match"]["scores"], s["match"]["innings"]) == after,
              f"the pasted link plays the same stroke from the same game: {s['match']}")
        overhead = g.screenshot("carom-2-overhead.png")
        g.click_widget("Change View")
        g.wait(lambda s: s["view"] == "cueball", 10, "the cue-ball view")
        time.sleep(2.5)
        cueview = g.screenshot("carom-3-cue-ball-view.png")
        check(differing_pixels(overhead, cueview) > 20000, "the cue-ball view shows the table from the cue ball")
    finally:
        g.close()


def practice_tables(exe, work):
    """Practice from New Game on the snooker table: the set-up drawn as snooker, no Hint; a red
    dragged to a free spot and refused onto the pink; a stroke; Try again; Save position writes
    the snooker table and balls that coolaaber-cli simulate reads; Load position brings them back;
    then practice on the three-cushion table; both views of each."""
    g = Game(exe, work, "--view", "overhead", "--seed", "3")
    try:
        g.wait(lambda s: not s["busy"] and s["frames"] >= 4, 30, "the first frames")
        g.click_widget("New Game...")
        g.click_widget("Snooker")
        g.click_widget("Practice (one player, no rules)")
        g.click_widget("Start")
        s = g.wait(lambda s: s["practice"] and s["look"] == "snooker" and not s["busy"], 30, "snooker practice")
        check(s["balls_on_table"] == 21 and s["match"] is None, f"the snooker set-up, no match: {s['balls_on_table']}")
        # The status of the frame that started practice lists the panel drawn before it.
        s = g.wait(lambda s: "Hint" not in s["widgets"] and "Strike" in s["widgets"], 10,
                   "Strike without Hint on the snooker table")
        time.sleep(0.5)
        g.screenshot("practice-snooker-1-setup.png")
        red = s["ball_px"]["3"]
        to = (red[0] - 260, red[1] + 40)
        drag(g, red, to)
        s = g.wait(lambda s: s["positions"]["3"] != g.status["positions"]["3"], 10, "the red moved")
        moved = s["ball_px"]["3"]
        check(abs(moved[0] - to[0]) < 3 and abs(moved[1] - to[1]) < 3, f"the red lies where it was dropped ({moved} for {to})")
        drag(g, moved, s["ball_px"]["20"])
        s = g.wait(lambda s: "on top of the pink" in s["refusal"], 10, "the refusal")
        check(s["refusal"] == "The red can't go on top of the pink.", f"the refusal names the balls: {s['refusal']!r}")
        before = s["positions"]
        key(g, "space")
        g.wait(lambda s: s["moving"], 10, "the stroke")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the balls to stop")
        check(s["positions"] != before and s["look"] == "snooker", f"the stroke moved the balls ({s['last_shot']!r})")
        g.screenshot("practice-snooker-2-shot.png")
        g.click_widget("Try again")
        g.wait(lambda s: s["positions"] == before, 10, "the position before the stroke")
        g.click_widget("Save position")
        s = g.wait(lambda s: "Saved the position" in s["link_note"], 10, "the save")
        saved = saved_position(work, before, 3.0)
        check(saved["table"]["length"] == 3.569 and saved["params"]["ball_radius"] == 0.02625,
              f"the 12 ft table and the snooker balls are saved: {saved['table']['length']}, {saved['params']['ball_radius']}")
        black = s["ball_px"]["21"]
        drag(g, black, (black[0] - 150, black[1] + 30))
        s = g.wait(lambda s: s["positions"] != before, 10, "the black moved")
        g.click_widget("Load position")
        s = g.wait(lambda s: "Loaded the position" in s["link_note"], 10, "the load")
        check(s["positions"] == before and s["look"] == "snooker", "Load position brings the snooker position back")
        overhead = g.screenshot("practice-snooker-3-overhead.png")
        g.click_widget("Change View")
        g.wait(lambda s: s["view"] == "cueball", 10, "the cue-ball view")
        time.sleep(2.5)
        cueview = g.screenshot("practice-snooker-4-cue-ball-view.png")
        check(differing_pixels(overhead, cueview) > 20000, "the cue-ball view shows the snooker table from the cue ball")

        g.click_widget("New Game...")
        g.click_widget("Three-cushion")
        g.click_widget("Practice (one player, no rules)")
        g.click_widget("Start")
        s = g.wait(lambda s: s["practice"] and s["look"] == "carom" and not s["busy"], 30, "three-cushion practice")
        check(s["balls_on_table"] == 2 and sorted(s["positions"]) == ["0", "1", "2"], f"white, yellow, red: {s['positions']}")
        time.sleep(2.5)
        cueview = g.screenshot("practice-carom-1-cue-ball-view.png")
        g.click_widget("Change View")
        g.wait(lambda s: s["view"] == "overhead", 10, "the overhead view")
        time.sleep(2.5)
        overhead = g.screenshot("practice-carom-2-overhead.png")
        check(differing_pixels(overhead, cueview) > 20000, "both views of the carom table drawn")
        key(g, "space")
        g.wait(lambda s: s["moving"], 10, "the stroke")
        s = g.wait(lambda s: not s["moving"] and not s["busy"], 60, "the balls to stop")
        check(s["last_shot"] == "Nothing was pocketed." and len(s["positions"]) == 3, f"three balls still: {s['positions']}")
        g.screenshot("practice-carom-3-shot.png")
    finally:
        g.close()


def headless_screenshot(exe, work):
    """--screenshot FILE draws the game's first frame without a window: the table and the whole
    panel (its text and buttons, not an empty panel), for a pool and a snooker table."""
    os.makedirs(work, exist_ok=True)
    for game in ("9ball", "snooker"):
        png = os.path.join(work, f"screenshot-{game}.png")
        p = subprocess.run([exe, "--game", game, "--screenshot", png], capture_output=True, text=True,
                           timeout=60, env=dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
                                                XDG_DATA_HOME=os.path.join(work, "data")))
        check(p.returncode == 0 and os.path.exists(png), f"--screenshot wrote {png} ({p.stderr.strip()!r})")
        spread = subprocess.run(["convert", png, "-crop", "300x720+980+0", "-colorspace", "gray",
                                 "-format", "%[fx:standard_deviation]", "info:"],
                                capture_output=True, text=True, check=True).stdout
        check(float(spread) > 0.08, f"the panel of {game} shows its text and buttons (grey spread {spread})")


if __name__ == "__main__":
    test, exe, work = sys.argv[1], sys.argv[2], sys.argv[3]
    {"controls": controls, "game": whole_game, "hinted": hinted_game, "display": no_display,
     "choice": no_choice_after_scratch, "kitchen": kitchen_foul, "guide": guide_marks,
     "resize": resize, "shot": shared_shot,
     "practice": practice, "screenshot": headless_screenshot, "snooker": snooker, "three_cushion": three_cushion,
     "practice_tables": practice_tables}[test](exe, work)
    print("passed")
