#!/usr/bin/env python3
"""The live web view in a real browser (issue 29): `ringloc run --http` on
the rendered rect drive played at 15 frames a second, its pose frames
through a pseudo-terminal decoded by `ringloc monitor`, the page loaded in
headless Chromium. Judged by the renderer's truth and the serial line:
every landmark id the page drew sits within 2 px of where the renderer put
that landmark (and a marker is on the canvas there), every landmark wholly
in view was drawn, the page's pose is within 1 cm of the pose frame of the
same capture time (and of the truth), the counters are shown, and the
image updates at least twice a second; the page is opened with ?token=
once and works on from the cookie, the token gone from its address. A
screenshot is kept.

usage: test_view_page.py RINGLOC PATHS_DIR TMPDIR"""
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_lib as vl  # noqa: E402

TOKEN = "page-t0ken"
SAMPLE_JS = """
const v = window.rlView, c = document.getElementById("cam"), g = c.getContext("2d");
const marks = v.labels.map(l => {
  const d = g.getImageData(Math.round(l.x) - 2, Math.round(l.y) - 2, 5, 5).data;
  for (let i = 0; i < d.length; i += 4)
    if (d[i] === 255 && d[i + 1] === 0 && d[i + 2] === 255) return true;
  return false;
});
const rows = Array.from(document.querySelectorAll("#nums tr")).map(r => r.innerText);
return {updates: v.updates, seq: v.seq, frame: v.frame, t_ms: v.t_ms, labels: v.labels, marks: marks,
        pose: v.pose, counters: v.counters, rows: rows, width: c.width, height: c.height,
        now: performance.now()};
"""


def sample_page(drv, seconds):
    samples, end = [], time.time() + seconds
    while time.time() < end:
        samples.append(drv.execute_script(SAMPLE_JS))
        time.sleep(0.3)
    return samples


WORST = {"label_px": 0.0, "serial_m": 0.0}


def check_labels(ck, s, paths_dir, names):
    t = vl.truth(paths_dir, names[s["frame"] % len(names)])
    where = {lm["id"]: lm for lm in t["landmarks"]}
    for lab, mark in zip(s["labels"], s["marks"]):
        lm = where.get(lab["id"])
        d = math.hypot(lab["x"] - lm["u"], lab["y"] - lm["v"]) if lm else 1e9
        WORST["label_px"] = max(WORST["label_px"], d)
        ck.check(d <= 2.0, "frame %d: id %d drawn at (%.2f, %.2f), %.2f px from the renderer's"
                 % (s["frame"], lab["id"], lab["x"], lab["y"], d))
        ck.check(mark, "frame %d: no centre marker on the canvas at id %d" % (s["frame"], lab["id"]))
    drawn = {lab["id"] for lab in s["labels"]}
    whole = [lm["id"] for lm in t["landmarks"] if lm["visible"] >= 1.0 and 30 < lm["u"] < 610 and 30 < lm["v"] < 450]
    missing = [i for i in whole if i not in drawn]
    ck.check(whole and not missing, "frame %d: landmarks in view not drawn: %s" % (s["frame"], missing))
    return len(s["labels"])


def check_pose(ck, s, poses, paths_dir, names):
    p = s["pose"]
    sent = [q for q in poses if q["type"] == "pose" and q["time_ms"] == s["t_ms"] % 2 ** 32]
    ck.check(len(sent) == 1, "frame %d (t %d ms): %d pose frames of that time on the line"
             % (s["frame"], s["t_ms"], len(sent)))
    if sent:
        d = math.hypot(p["x"] - sent[0]["x"], p["y"] - sent[0]["y"])
        WORST["serial_m"] = max(WORST["serial_m"], d)
        ck.check(d <= 0.01 and abs(p["yaw"] - sent[0]["yaw"]) <= 0.001,
                 "frame %d: page pose %s vs serial %s" % (s["frame"], p, sent[0]))
    t = vl.truth(paths_dir, names[s["frame"] % len(names)])
    d = math.hypot(p["x"] - t["x"], p["y"] - t["y"])
    ck.check(d <= 0.01, "frame %d: page pose (%.4f, %.4f) %.4f m from the truth" % (s["frame"], p["x"], p["y"], d))
    return d


def check_counters(ck, s):
    k = s["counters"] or {}
    for key in ("fps", "latency_ms", "landmarks_per_frame", "frames", "poses", "statuses", "dropped", "reasons"):
        ck.check(key in k and k[key] is not None, "counter %s missing" % key)
    ck.check(k.get("fps") and abs(k["fps"] - vl.RATE) < 3, "frame rate %s, the replay's is %d" % (k.get("fps"), vl.RATE))
    names = [r.split("\t")[0] for r in s["rows"]]
    for row in ("pose", "sigma", "frame rate", "latency", "landmarks per frame", "frames", "camera", "serial",
                "recording"):
        ck.check(row in names, "the numbers table has no '%s' row (%s)" % (row, names))


def main():
    ringloc, paths_dir, tmp = sys.argv[1:4]
    vl.browser_or_skip()
    os.makedirs(tmp, exist_ok=True)
    names = vl.frames_of(paths_dir)
    mon, tty = vl.start_monitor(ringloc, tmp)
    cfg = vl.write_config(tmp, paths_dir, names, tty)
    port = vl.free_port()
    with open(cfg, "a") as f:  # with a token: given once in the address, then a cookie (issue 39)
        f.write("http: {listen: 127.0.0.1:%d, token: %s}\n" % (port, TOKEN))
    fw = vl.start_firmware(ringloc, cfg, tmp, 30 * vl.RATE)  # ended once sampled
    drv = None
    ck = vl.Checks()
    try:
        vl.wait_http(port, fw)
        drv = vl.chromium()
        drv.get("http://127.0.0.1:%d/?token=%s" % (port, TOKEN))
        end = time.time() + 15
        while time.time() < end and not drv.execute_script("return window.rlView && window.rlView.updates > 1"):
            time.sleep(0.1)
        samples = sample_page(drv, 4.0)
        address = drv.current_url
        drv.save_screenshot(os.path.join(tmp, "view.png"))
    finally:
        if drv:
            drv.quit()
        fw.terminate()
        fw.wait(10)
        try:
            mon.wait(5)
        except subprocess.TimeoutExpired:
            mon.kill()
    poses = [__import__("json").loads(x) for x in open(os.path.join(tmp, "poses.jsonl")) if x.strip()]
    ck.check(len(samples) >= 5 and samples[-1]["updates"] > 1, "the page never showed a frame")
    ck.check(TOKEN not in address, "the token stayed in the address bar: %s" % address)
    if ck.failed:
        return ck.done()
    first, last = samples[0], samples[-1]
    rate = (last["updates"] - first["updates"]) / ((last["now"] - first["now"]) / 1000.0)
    ck.check(rate >= 2.0, "the image updated %.2f times a second (at least 2)" % rate)
    ck.check(len({s["seq"] for s in samples}) >= 6, "only %d distinct snapshots in %d samples"
             % (len({s["seq"] for s in samples}), len(samples)))
    ck.check(first["width"] == 640 and first["height"] == 480, "canvas %dx%d" % (first["width"], first["height"]))
    labels, worst = 0, 0.0
    for s in samples:
        labels += check_labels(ck, s, paths_dir, names)
        worst = max(worst, check_pose(ck, s, poses, paths_dir, names))
    check_counters(ck, last)
    print("view: %d samples, %d ids checked (at most %.2f px from the renderer's), %.2f updates/s, pose within "
          "%.4f m of the serial line's and %.4f m of the truth, %d pose frames; screenshot %s"
          % (len(samples), labels, WORST["label_px"], rate, WORST["serial_m"], worst, len(poses),
             os.path.join(tmp, "view.png")))
    return ck.done()


if __name__ == "__main__":
    vl.run(main)
