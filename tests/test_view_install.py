#!/usr/bin/env python3
"""The live web view as an installer under a robot uses it (issue 41):
`ringloc run --http` on the rendered rect drive at 15 frames a second, its
pose frames through a pseudo-terminal, the page in headless Chromium.
Judged against the renderer's truth and hand-made expectations:
 - at 390 px and 360 px wide nothing needs sideways scrolling
   (document.scrollingElement.scrollWidth <= innerWidth, which is the
   phone's width: a page too wide is zoomed out) and the panels
   are stacked; at 1280 px the map stands beside the camera;
Screenshots go to TMPDIR (view-*.png; docs/ holds copies).

usage: test_view_install.py RINGLOC PATHS_DIR TMPDIR"""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_lib as vl  # noqa: E402

LAYOUT_JS = """
const se = document.scrollingElement, cam = document.getElementById("cam").getBoundingClientRect(),
      map = document.getElementById("map").getBoundingClientRect();
return {scroll: se.scrollWidth, inner: window.innerWidth, updates: window.rlView.updates,
        cam: [cam.left, cam.top, cam.right], map: [map.left, map.top, map.right]};
"""


def wait_updates(drv, n=2, seconds=15):
    end = time.time() + seconds
    while time.time() < end:
        if drv.execute_script("return window.rlView && window.rlView.updates >= %d" % n):
            return True
        time.sleep(0.1)
    return False


def check_layout(ck, port, tmp):
    for width, height, stacked in ((390, 1900, True), (360, 1900, True), (1280, 900, False)):
        drv = vl.chromium(width, height, phone=stacked)
        try:
            drv.get("http://127.0.0.1:%d/" % port)
            ck.check(wait_updates(drv), "%d px: the page never showed a frame" % width)
            time.sleep(0.6)  # the numbers and the map drawn too
            lay = drv.execute_script(LAYOUT_JS)
            drv.save_screenshot(os.path.join(tmp, "view-%d.png" % width))
        finally:
            drv.quit()
        ck.check(lay["inner"] == width, "%d px: the window is %s px wide" % (width, lay["inner"]))
        ck.check(lay["scroll"] <= min(lay["inner"], width), "%d px: the page is %s px wide, %s px show: it scrolls sideways"
                 % (width, lay["scroll"], lay["inner"]))
        beside = lay["map"][0] >= lay["cam"][2]
        ck.check(beside != stacked, "%d px: the map is %s the camera (%s vs %s)"
                 % (width, "beside" if beside else "below", lay["map"], lay["cam"]))
        print("layout %d px: page %s px wide, map %s the camera" % (width, lay["scroll"],
                                                                    "beside" if beside else "below"))


def main():
    ringloc, paths_dir, tmp = sys.argv[1:4]
    vl.browser_or_skip()
    os.makedirs(tmp, exist_ok=True)
    names = vl.frames_of(paths_dir)
    tty = os.path.join(tmp, "tty")
    if os.path.lexists(tty):
        os.remove(tty)
    cfg = vl.write_config(tmp, paths_dir, names, tty)
    port = vl.free_port()
    with open(cfg, "a") as f:
        f.write("http: {listen: 127.0.0.1:%d}\n" % port)
    mon = subprocess.Popen([ringloc, "monitor", "--pty", tty], stdout=open(os.path.join(tmp, "poses.jsonl"), "w"),
                           stderr=open(os.path.join(tmp, "monitor.err"), "w"))
    for _ in range(50):
        if os.path.islink(tty):
            break
        time.sleep(0.1)
    fw = vl.start_firmware(ringloc, cfg, tmp, 120 * vl.RATE)
    ck = vl.Checks()
    try:
        vl.wait_http(port, fw)
        check_layout(ck, port, tmp)
    finally:
        fw.terminate()
        fw.wait(10)
        if mon.poll() is None:
            mon.terminate()
            mon.wait(5)
    return ck.done()


if __name__ == "__main__":
    vl.run(main)
