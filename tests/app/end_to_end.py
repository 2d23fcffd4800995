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
"""
import json
import os
import shutil
import subprocess
import sys
import time


class Game:
    def __init__(self, exe, work, *args):
        self.work = work
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
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


if __name__ == "__main__":
    test, exe, work = sys.argv[1], sys.argv[2], sys.argv[3]
    {"controls": controls, "game": whole_game, "hinted": hinted_game}[test](exe, work)
    print("passed")
