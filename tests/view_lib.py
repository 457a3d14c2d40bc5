"""What the web view's browser tests share: rendered frames played as a
camera at 15 frames a second, the firmware run on them with its pose
frames decoded by `ringloc monitor`, headless Chromium through Debian's
python3-selenium, and the renderer's truth. Exit code 77 (CTest's skip)
when Chromium, its driver or selenium is absent."""
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import time

SKIP = 77
RATE = 15


class Fail(Exception):
    pass


def browser_or_skip():
    try:
        from selenium import webdriver  # noqa: F401
    except ImportError:
        print("SKIP: python3-selenium is not installed (tools/deps.sh host installs it)")
        sys.exit(SKIP)
    for exe in ("chromium", "chromedriver"):
        if not shutil.which(exe) and not os.path.exists("/usr/bin/" + exe):
            print("SKIP: %s is not installed (tools/deps.sh host installs it)" % exe)
            sys.exit(SKIP)


def chromium(width=1280, height=900, tmp=None, phone=False):
    """Headless Chromium; phone: as a phone of width x height (mobile
    emulation: a window is never narrower than 500 px); with tmp, at the lowest priority (through a
    wrapper there), as if it ran on another computer: on CI's shared cores
    a browser would otherwise take the loop's time, not the server."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    opts = webdriver.ChromeOptions()
    binary = shutil.which("chromium") or "/usr/bin/chromium"
    if tmp:
        wrapper = os.path.join(tmp, "chromium-nice")
        with open(wrapper, "w") as f:
            f.write('#!/bin/sh\nexec nice -n 19 %s "$@"\n' % binary)
        os.chmod(wrapper, 0o755)
        binary = wrapper
    opts.binary_location = binary
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--force-device-scale-factor=1", "--window-size=%d,%d" % (max(width, 500), height)):
        opts.add_argument(a)
    if phone:
        opts.add_experimental_option("mobileEmulation", {"deviceMetrics": {"width": width, "height": height,
                                                                           "pixelRatio": 1.0}})
    drv = shutil.which("chromedriver") or "/usr/bin/chromedriver"
    return webdriver.Chrome(service=Service(drv), options=opts)


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def frames_of(paths_dir, pattern=r"rect_\d+\.png"):
    names = sorted(n for n in os.listdir(paths_dir) if re.fullmatch(pattern, n))
    if not names:
        raise Fail("no frames matching %s in %s" % (pattern, paths_dir))
    return names


def truth(paths_dir, png):
    """The renderer's truth of a frame: the robot's pose and each landmark's
    id, u, v and visible fraction."""
    text = open(os.path.join(paths_dir, png[:-4] + ".yaml")).read()
    m = re.search(r"^robot: \{x: ([-0-9.]+), y: ([-0-9.]+), yaw: ([-0-9.]+)\}", text, re.M)
    lms = [dict(id=int(a), u=float(b), v=float(c), visible=float(d)) for a, b, c, d in
           re.findall(r"\{id: (\d+), x: [-0-9.]+, y: [-0-9.]+, u: ([-0-9.]+), v: ([-0-9.]+), "
                      r"radius: [-0-9.]+, visible: ([-0-9.]+)", text)]
    return dict(x=float(m.group(1)), y=float(m.group(2)), yaw=float(m.group(3)), landmarks=lms)


def write_config(tmp, paths_dir, names, serial, loop=True):
    with open(os.path.join(tmp, "frames.txt"), "w") as f:
        for n in names:
            f.write(os.path.join(paths_dir, n) + "\n")
    cfg = os.path.join(tmp, "ringloc.yaml")
    with open(cfg, "w") as f:
        f.write("camera: {backend: png, device: frames.txt, width: 640, height: 480, rate: %d, loop: %s}\n"
                % (RATE, "true" if loop else "false"))
        f.write("calibration: %s/camera.yaml\nmap: %s/map.yaml\nrobot: %s/robot.yaml\n"
                % (paths_dir, paths_dir, paths_dir))
        f.write("serial: {device: %s, baud: 115200}\nrecognition: {local: auto}\n" % serial)
    return cfg


def start_firmware(ringloc, cfg, tmp, frames, http=None, tag="run"):
    args = [ringloc, "run", "--config", cfg, "--frames", str(frames)]
    if http:
        args += ["--http", http]
    err = open(os.path.join(tmp, tag + ".err"), "w")
    return subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=err)


def wait_http(port, proc, seconds=10):
    end = time.time() + seconds
    while time.time() < end:
        if proc.poll() is not None:
            raise Fail("the firmware exited %s before serving" % proc.returncode)
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.5).close()
            return
        except OSError:
            time.sleep(0.05)
    raise Fail("nothing listening on port %d after %d s" % (port, seconds))


def start_monitor(ringloc, tmp):
    """`ringloc monitor --pty` decoding the pose frames into
    tmp/poses.jsonl: returns it and the pty's link (tmp/tty), once there."""
    tty = os.path.join(tmp, "tty")
    if os.path.lexists(tty):
        os.remove(tty)
    mon = subprocess.Popen([ringloc, "monitor", "--pty", tty], stdout=open(os.path.join(tmp, "poses.jsonl"), "w"),
                           stderr=open(os.path.join(tmp, "monitor.err"), "w"))
    for _ in range(50):
        if os.path.islink(tty):
            break
        time.sleep(0.1)
    return mon, tty


def decode(ringloc, serial_file):
    out = subprocess.run([ringloc, "monitor", serial_file], capture_output=True, text=True, check=True).stdout
    return [json.loads(line) for line in out.splitlines() if line.strip()]


def same_pose(a, b):
    """Everything a pose frame says but its times."""
    keys = ("type", "seq", "x", "y", "yaw", "landmarks_used", "flags", "residual", "sigma", "tilt")
    return all(a.get(k) == b.get(k) for k in keys)


class Checks:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print("FAIL: " + what)

    def done(self):
        print("%d passed, %d failed" % (self.passed, self.failed))
        return 1 if self.failed else 0


def run(main):
    """A view test's entry: main's status, or 1 with the line of a Fail."""
    try:
        sys.exit(main())
    except Fail as e:
        print("FAIL: %s" % e)
        sys.exit(1)


def png_gray(data):
    """An 8-bit grey, non-interlaced PNG's (width, height, rows): an
    oracle of its own (zlib and the five row filters), not libpng."""
    import struct
    import zlib
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise Fail("not a PNG")
    pos, idat, w = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour != 0 or interlace:
                raise Fail("not an 8-bit grey PNG (depth %d, colour type %d)" % (depth, colour))
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, rows, prev = zlib.decompress(idat), [], bytearray(w)
    for y in range(h):
        f, line = raw[y * (w + 1)], bytearray(raw[y * (w + 1) + 1:(y + 1) * (w + 1)])
        for x in range(w):
            a = line[x - 1] if x else 0
            b, c = prev[x], (prev[x - 1] if x else 0)
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, rows
