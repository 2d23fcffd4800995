#!/usr/bin/env python3
"""The running game's frame rate, as a player sees it: the real `coolaaber` window under a
virtual display, driven with xdotool; Mesa's HUD (GALLIUM_HUD=fps, dumped every 0.25 s) counts
the frames shown. Run it under xvfb-run:

  xvfb-run -a -s "-screen 0 1280x720x24" bench/game_fps.py COOLAABER [WORKDIR]

Prints one JSON line per case:
  break_overhead   the 8-ball break (seed 3) in the overhead view, while the balls move
  break_cueball    the same break in the cue-ball view (the camera stays still during a shot)
  aim_cueball      aiming in the cue-ball view, the mouse turning the aim back and forth (the
                   camera moves every frame)
and the start-up: from exec to the first frame shown (the status file's first write), median of
the runs. Medians of the HUD's 0.25 s samples; a software renderer only (GALLIUM_HUD is Mesa's).
cpu_ms_per_frame: the game process's CPU time (all its threads, llvmpipe's included) over the
measured stretch divided by the frames shown in it, a figure that depends less on what else the
machine runs than the frame rate does (compare builds by it on a busy machine).
"""
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

HUD_PERIOD = 0.25


class Run:
    def __init__(self, exe, work, view):
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        self.work = work
        self.status_path = os.path.join(work, "status.json")
        self.fps_path = os.path.join(work, "fps")
        env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
                   XDG_DATA_HOME=os.path.join(work, "data"), ALSOFT_DRIVERS="null",
                   GALLIUM_HUD="simple,fps", GALLIUM_HUD_DUMP_DIR=work,
                   GALLIUM_HUD_PERIOD=str(HUD_PERIOD))
        self.start = time.time()
        self.proc = subprocess.Popen([exe, "--size", "1280x720", "--status-file", self.status_path,
                                      "--seed", "3", "--game", "8ball", "--players", "human,human",
                                      "--view", view], env=env, stderr=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL)
        while not os.path.exists(self.status_path):
            if time.time() - self.start > 30 or self.proc.poll() is not None:
                raise SystemExit("the game showed no first frame")
            time.sleep(0.005)
        self.first_frame = time.time() - self.start
        out = subprocess.run(["xdotool", "search", "--sync", "--name", "^Coolaaber$"],
                             capture_output=True, text=True, timeout=30)
        self.window = out.stdout.split()[0]
        self.samples_read = 0

    def status(self):
        try:
            with open(self.status_path) as f:
                return json.load(f)
        except (OSError, ValueError):
            return None

    def wait(self, pred, timeout):
        end = time.time() + timeout
        while time.time() < end:
            s = self.status()
            if s is not None and pred(s):
                return s
            time.sleep(0.05)
        raise SystemExit(f"timed out; last status {self.status()}")

    def cpu_seconds(self):
        with open(f"/proc/{self.proc.pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def new_samples(self):
        """The HUD's samples written since the last call."""
        try:
            with open(self.fps_path) as f:
                values = [float(x) for x in f.read().split()]
        except OSError:
            values = []
        fresh = values[self.samples_read:]
        self.samples_read = len(values)
        return fresh

    def xdo(self, *args):
        subprocess.run(["xdotool", *args], check=True, timeout=60)

    def close(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()


def measure_break(exe, work, view):
    r = Run(exe, work, view)
    try:
        r.wait(lambda s: s["phase"] == "shoot" and not s["busy"], 30)
        r.xdo("mousemove", "--window", r.window, "480", "400")
        time.sleep(0.5)
        r.new_samples()
        r.xdo("click", "--window", r.window, "3")  # a right click strikes
        r.wait(lambda s: s["shots"] == 1, 10)
        time.sleep(0.6)  # the stroke and the first samples' partial period
        r.new_samples()
        cpu0 = r.cpu_seconds()
        end = time.time() + 4.0
        while time.time() < end and r.status()["busy"]:
            time.sleep(0.1)
        cpu = r.cpu_seconds() - cpu0
        samples = r.new_samples()
        return samples[:-1], r.first_frame, cpu, sum(samples) * HUD_PERIOD
    finally:
        r.close()


def measure_aim(exe, work):
    r = Run(exe, work, "cueball")
    try:
        r.wait(lambda s: s["phase"] == "shoot" and not s["busy"], 30)
        r.xdo("mousemove", "--window", r.window, "480", "400")
        time.sleep(1.0)  # the view's glide to the cue ball
        r.xdo("mousedown", "--window", r.window, "3")
        # One xdotool process moves the mouse back and forth for about 6 s.
        chain = []
        for sweep in range(6):
            xs = range(440, 521, 4) if sweep % 2 == 0 else range(520, 439, -4)
            for x in xs:
                chain += ["mousemove", "--window", r.window, str(x), "400", "sleep", "0.05"]
        mover = subprocess.Popen(["xdotool", *chain])
        time.sleep(1.0)
        r.new_samples()
        cpu0 = r.cpu_seconds()
        mover.wait(timeout=60)
        cpu = r.cpu_seconds() - cpu0
        samples = r.new_samples()
        return samples[:-1], r.first_frame, cpu, sum(samples) * HUD_PERIOD
    finally:
        r.close()


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    exe = sys.argv[1]
    work = sys.argv[2] if len(sys.argv) > 2 else "/tmp/coolaaber-game-fps"
    starts = []
    for name, fn in [("break_overhead", lambda w: measure_break(exe, w, "overhead")),
                     ("break_cueball", lambda w: measure_break(exe, w, "cueball")),
                     ("aim_cueball", lambda w: measure_aim(exe, w))]:
        samples, first, cpu, frames = fn(os.path.join(work, name))
        starts.append(first)
        print(json.dumps({"case": name, "fps_median": round(statistics.median(samples), 1),
                          "fps_min": round(min(samples), 1), "samples": len(samples),
                          "cpu_ms_per_frame": round(1000 * cpu / max(frames, 1), 1)}), flush=True)
    print(json.dumps({"case": "first_frame", "seconds_median": round(statistics.median(starts), 3),
                      "runs": [round(s, 3) for s in starts]}), flush=True)


if __name__ == "__main__":
    main()
