#!/usr/bin/env python3
"""The robot never stops localizing for a side feature (issue 39). The
firmware runs on the rendered rect drive with its serial line on a pty,
as a robot's controller would read it:
  1. the web view's port taken at start: pose frames flow all the same,
     one line says why, and the view is served once the port is free;
  2. a recording folder that is read-only, and one that holds 999 drives:
     every pose frame is sent, one line says why, no drive is made;
  3. recording stopped by max_mb: the page says it is off (and why), its
     "kept" stops counting, the pose frames go on;
  4. a run that records no frame (the camera never opens) leaves no empty
     drive_NNN behind;
  5. the web view heard beyond loopback without a token: a token made and
     printed, asked before anything else (401 with WWW-Authenticate), the
     URL's token returned as an HttpOnly cookie, a Host not the robot's
     refused, a request trickled byte by byte closed at its deadline;
  6. the service's watchdog: with a fake NOTIFY_SOCKET, READY=1, then
     WATCHDOG=1 pings while frames flow, and none while the camera is
     down.
Nothing asserted depends on the machine's load: frames are counted, never
timed.

usage: test_service.py RINGLOC PATHS_DIR TMPDIR"""
import json
import os
import select
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.request

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import view_lib as vl  # noqa: E402


class Pty:
    """A pty whose far end the firmware writes pose frames to; the bytes
    read here, decoded by `ringloc monitor`."""

    def __init__(self, tmp, tag):
        self.master, self.slave = os.openpty()
        self.name = os.ttyname(self.slave)
        self.path = os.path.join(tmp, tag + ".bin")
        self.data = bytearray()
        self.lock = threading.Lock()
        self.quit = False
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self):
        while not self.quit:
            r, _, _ = select.select([self.master], [], [], 0.1)
            if r:
                try:
                    b = os.read(self.master, 65536)
                except OSError:
                    continue
                with self.lock:
                    self.data += b

    def frames(self, ringloc):
        with self.lock:
            data = bytes(self.data)
        with open(self.path, "wb") as f:
            f.write(data)
        return vl.decode(ringloc, self.path)

    def poses(self, ringloc):
        return [p for p in self.frames(ringloc) if p["type"] == "pose"]

    def close(self):
        self.quit = True
        self.thread.join()
        os.close(self.master)
        os.close(self.slave)


def config(tmp, paths_dir, tag, serial, loop, extra=""):
    names = vl.frames_of(paths_dir)
    frames = os.path.join(tmp, tag + "_frames.txt")
    with open(frames, "w") as f:
        for n in names:
            f.write(os.path.join(paths_dir, n) + "\n")
    cfg = os.path.join(tmp, tag + ".yaml")
    with open(cfg, "w") as f:
        f.write("camera: {backend: png, device: %s, width: 640, height: 480, rate: 15, loop: %s}\n"
                % (frames, "true" if loop else "false"))
        f.write("calibration: %s/camera.yaml\nmap: %s/map.yaml\nrobot: %s/robot.yaml\n"
                % (paths_dir, paths_dir, paths_dir))
        f.write("serial: {device: %s, baud: 115200}\n%s" % (serial, extra))
    return cfg, len(names)


def start(ringloc, cfg, tmp, tag, args=(), env=None):
    err = open(os.path.join(tmp, tag + ".err"), "w")
    return subprocess.Popen([ringloc, "run", "--config", cfg] + list(args), stdout=subprocess.DEVNULL,
                            stderr=err, env=env)


def err_of(tmp, tag):
    with open(os.path.join(tmp, tag + ".err")) as f:
        return f.read()


def wait_for(cond, proc, seconds=30):
    """Poll cond until true, the firmware gone or the time up (a bound for
    a hung run, not a measurement)."""
    end = time.time() + seconds
    while time.time() < end:
        if cond():
            return True
        if proc is not None and proc.poll() is not None:
            return cond()
        time.sleep(0.1)
    return False


def stop(proc):
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
    return proc.wait(30)


def status(port):
    req = urllib.request.Request("http://127.0.0.1:%d/status.json" % port, headers={"Host": "127.0.0.1"})
    with urllib.request.urlopen(req, timeout=5) as r:
        return json.loads(r.read().decode())


def status_or_none(port):
    try:
        return status(port)
    except (OSError, ValueError):
        return None


def serving(port):
    return status_or_none(port) is not None


def port_taken(ringloc, paths_dir, tmp, ck):
    pty = Pty(tmp, "taken")
    blocker = socket.socket()
    blocker.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    blocker.bind(("127.0.0.1", 0))
    blocker.listen(1)
    port = blocker.getsockname()[1]
    cfg, _ = config(tmp, paths_dir, "taken", pty.name, True)
    fw = start(ringloc, cfg, tmp, "taken", ["--http", "127.0.0.1:%d" % port])
    try:
        ok = wait_for(lambda: len(pty.poses(ringloc)) >= 20, fw)
        ck.check(ok, "port taken: %d pose frames before the port was freed (rc %s): %s"
                 % (len(pty.poses(ringloc)), fw.poll(), err_of(tmp, "taken")))
        lines = [ln for ln in err_of(tmp, "taken").splitlines() if "cannot listen" in ln]
        ck.check(len(lines) == 1 and ("127.0.0.1:%d" % port) in lines[0],
                 "port taken: one line naming the address, got %s" % lines)
        blocker.close()
        ok = wait_for(lambda: serving(port), fw)
        ck.check(ok, "port freed: the web view is served (rc %s): %s" % (fw.poll(), err_of(tmp, "taken")))
        before = len(pty.poses(ringloc))
        ok = wait_for(lambda: len(pty.poses(ringloc)) >= before + 10, fw)
        ck.check(ok, "port freed: pose frames go on (%d, then %d)" % (before, len(pty.poses(ringloc))))
        seqs = [p["seq"] for p in pty.frames(ringloc)]
        ck.check(all(b == (a + 1) % 65536 for a, b in zip(seqs, seqs[1:])), "port taken: seq has gaps")
    finally:
        rc = stop(fw)
        pty.close()
    ck.check(rc == 0, "port taken: exit status %d" % rc)


def no_drive(ringloc, paths_dir, tmp, ck, tag, folder, expect):
    """A recording folder that cannot take a drive: every pose frame, one
    line, nothing made in it."""
    pty = Pty(tmp, tag)
    cfg, n = config(tmp, paths_dir, tag, pty.name, False)
    drives = lambda: sorted(d for d in os.listdir(folder) if d.startswith("drive_"))  # noqa: E731
    before = drives()
    fw = start(ringloc, cfg, tmp, tag, ["--record", folder])
    rc = fw.wait(60)
    time.sleep(0.3)  # the last bytes through the pty
    poses = pty.poses(ringloc)
    pty.close()
    err = err_of(tmp, tag)
    lines = [ln for ln in err.splitlines() if "record:" in ln]
    ck.check(rc == 0 and len(poses) == n, "%s: rc %d, %d pose frames for %d frames: %s" % (tag, rc, len(poses), n, err))
    ck.check(len(lines) == 1 and expect in lines[0], "%s: one line saying '%s', got %s" % (tag, expect, lines))
    ck.check(drives() == before, "%s: drives made: %s" % (tag, sorted(set(drives()) - set(before))))


def recording_stops(ringloc, paths_dir, tmp, ck):
    pty = Pty(tmp, "maxmb")
    port = vl.free_port()
    rec = os.path.join(tmp, "rec_maxmb")
    cfg, _ = config(tmp, paths_dir, "maxmb", pty.name, True, "record: {dir: %s, every: 1, max_mb: 0.1}\n" % rec)
    fw = start(ringloc, cfg, tmp, "maxmb", ["--http", "127.0.0.1:%d" % port])
    try:
        ok = wait_for(lambda: "recording stopped" in err_of(tmp, "maxmb") and serving(port), fw)
        ck.check(ok, "max_mb: recording stopped: %s" % err_of(tmp, "maxmb"))
        ok = wait_for(lambda: not (status_or_none(port) or {"recording": {"on": 1}})["recording"]["on"], fw, 10)
        st = status_or_none(port) or {"recording": {"kept": -1}, "counters": {"frames": 0}}
        ck.check(ok and "max_mb" in st["recording"].get("note", ""),
                 "max_mb: the page says recording is on after it stopped: %s" % st["recording"])
        frames = st["counters"]["frames"]
        ok = wait_for(lambda: (status_or_none(port) or {"counters": {"frames": 0}})["counters"]["frames"] >= frames + 10, fw)
        st2 = status_or_none(port) or {"recording": {"kept": -2}, "counters": {"frames": 0}}
        ck.check(ok and st2["recording"]["kept"] == st["recording"]["kept"],
                 "max_mb: 'kept' counts on after the stop: %d, then %d (frames %d, then %d)"
                 % (st["recording"]["kept"], st2["recording"]["kept"], frames, st2["counters"]["frames"]))
    finally:
        rc = stop(fw)
        pty.close()
    ck.check(rc == 0, "max_mb: exit status %d" % rc)


def camera_down_config(tmp, paths_dir, tag, serial):
    cfg = os.path.join(tmp, tag + ".yaml")
    with open(cfg, "w") as f:
        f.write("camera: {backend: v4l2, device: /dev/video_ringloc_none, width: 640, height: 480}\n")
        f.write("calibration: %s/camera.yaml\nmap: %s/map.yaml\nrobot: %s/robot.yaml\n"
                % (paths_dir, paths_dir, paths_dir))
        f.write("serial: {device: %s, baud: 115200}\n" % serial)
    return cfg


def empty_drive(ringloc, paths_dir, tmp, ck):
    pty = Pty(tmp, "empty")
    rec = os.path.join(tmp, "rec_empty")
    fw = start(ringloc, camera_down_config(tmp, paths_dir, "empty", pty.name), tmp, "empty", ["--record", rec])
    try:
        ok = wait_for(lambda: len(pty.frames(ringloc)) >= 3, fw)
        ck.check(ok, "camera down: status frames go out: %s" % err_of(tmp, "empty"))
    finally:
        rc = stop(fw)
        pty.close()
    left = os.listdir(rec) if os.path.isdir(rec) else []
    ck.check(rc == 0 and not left, "a run that recorded nothing left %s (rc %d): %s" % (left, rc, err_of(tmp, "empty")))


class Notify:
    """A fake NOTIFY_SOCKET: the datagrams the firmware sends, in order."""

    def __init__(self, tmp):
        self.path = os.path.join(tmp, "notify.sock")
        if os.path.exists(self.path):
            os.remove(self.path)
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        self.sock.bind(self.path)
        self.sock.settimeout(0.1)
        self.got = []

    def read(self):
        while True:
            try:
                self.got.append(self.sock.recv(4096).decode())
            except socket.timeout:
                return self.got

    def count(self, what):
        return sum(what in m.split("\n") for m in self.read())

    def close(self):
        self.sock.close()


def watchdog(ringloc, paths_dir, tmp, ck):
    env = dict(os.environ, WATCHDOG_USEC="400000")
    for tag, flowing in (("notify", True), ("notify_down", False)):
        note = Notify(tmp)
        env["NOTIFY_SOCKET"] = note.path
        pty = Pty(tmp, tag)
        if flowing:
            cfg, _ = config(tmp, paths_dir, tag, pty.name, True)
        else:
            cfg = camera_down_config(tmp, paths_dir, tag, pty.name)
        fw = start(ringloc, cfg, tmp, tag, env=env)
        try:
            ok = wait_for(lambda: note.count("READY=1") == 1, fw)
            ck.check(ok, "%s: READY=1 sent: %s (%s)" % (tag, note.got, err_of(tmp, tag)))
            # frames counted, not time: 30 frames at 15 a second is 2 s, five watchdog periods
            ok = wait_for(lambda: len(pty.frames(ringloc)) >= 30, fw)
            ck.check(ok, "%s: 30 frames on the line" % tag)
            pings = note.count("WATCHDOG=1")
            if flowing:
                ck.check(pings >= 1, "%s: no WATCHDOG=1 while frames flow: %s" % (tag, note.got))
            else:
                ck.check(pings == 0, "%s: %d WATCHDOG=1 with the camera down" % (tag, pings))
        finally:
            rc = stop(fw)
            pty.close()
        ck.check(rc == 0 and note.count("STOPPING=1") == 1, "%s: rc %d, STOPPING=1 sent: %s" % (tag, rc, note.got))
        note.close()


def raw_http(port, raw, source="127.0.0.1"):
    """Send raw bytes, return the status and the headers (lower-case names)."""
    s = socket.create_connection(("127.0.0.1", port), timeout=10, source_address=(source, 0))
    s.sendall(raw)
    data = b""
    while b"\r\n\r\n" not in data:
        b = s.recv(4096)
        if not b:
            break
        data += b
    s.close()
    head = data.split(b"\r\n\r\n")[0].decode("latin-1").split("\r\n")
    parts = head[0].split(" ")
    code = int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else 0
    hdrs = {}
    for ln in head[1:]:
        k, _, v = ln.partition(":")
        hdrs.setdefault(k.strip().lower(), []).append(v.strip())
    return code, hdrs


def trickle(port, source, limit):
    """One header byte every 0.1 s: the bytes sent before the server
    closed the connection, or limit when it never did."""
    s = socket.create_connection(("127.0.0.1", port), timeout=10, source_address=(source, 0))
    s.sendall(b"GET /status.json HTTP/1.1\r\nHost: 127.0.0.1\r\n")
    sent = 0
    try:
        while sent < limit:
            s.sendall(b"X-a: b\r\n"[sent % 8:sent % 8 + 1])
            sent += 1
            r, _, _ = select.select([s], [], [], 0.1)
            if r and not s.recv(4096):
                break
    except OSError:
        pass
    s.close()
    return sent


def web_security(ringloc, paths_dir, tmp, ck):
    """Heard beyond loopback without a token: one is made and printed; the
    token before anything, 401 with WWW-Authenticate, the token from the
    URL returned as a cookie, a foreign Host refused, a trickling request
    closed at its deadline however it trickles."""
    pty = Pty(tmp, "web")
    port = vl.free_port()
    cfg, _ = config(tmp, paths_dir, "web", pty.name, True, "http: {listen: 0.0.0.0:%d}\n" % port)
    fw = start(ringloc, cfg, tmp, "web")
    try:
        ok = wait_for(lambda: "the token for this run is" in err_of(tmp, "web"), fw)
        ck.check(ok, "0.0.0.0 without http.token: no token made: %s" % err_of(tmp, "web"))
        token = err_of(tmp, "web").split("the token for this run is ")[-1].split(" ")[0] if ok else "x"
        vl.wait_http(port, fw)
        get = "GET %s HTTP/1.1\r\nHost: %s\r\n%s\r\n"
        code, h = raw_http(port, (get % ("/nothing", "127.0.0.1", "")).encode())
        ck.check(code == 401 and "www-authenticate" in h, "no token: %d %s (401 with WWW-Authenticate)" % (code, h))
        code, h = raw_http(port, (get % ("/?token=" + token, "127.0.0.1", "")).encode())
        cookie = (h.get("set-cookie") or [""])[0]
        ck.check(code == 303 and cookie.startswith("ringloc_token=" + token + ";") and "HttpOnly" in cookie,
                 "token in the URL: %d, cookie %r" % (code, cookie))
        code, _ = raw_http(port, (get % ("/status.json", "127.0.0.1", "Cookie: ringloc_token=%s\r\n" % token)).encode())
        ck.check(code == 200, "the cookie alone: %d" % code)
        code, _ = raw_http(port, (get % ("/status.json?token=" + token, "evil.example:%d" % port, "")).encode())
        ck.check(code == 421, "a rebinding Host: %d" % code)
        # 10 s of deadline: a per-byte idle timeout would never close it (600 bytes: 60 s)
        sent = trickle(port, "127.0.0.2", 600)
        ck.check(sent < 600, "a request trickled a byte every 0.1 s was never closed (%d bytes)" % sent)
        ck.check(serving(port) or raw_http(port, (get % ("/status.json", "127.0.0.1",
                                                          "Cookie: ringloc_token=%s\r\n" % token)).encode())[0] == 200,
                 "served after the trickle")
    finally:
        rc = stop(fw)
        pty.close()
    ck.check(rc == 0 and len(pty.poses(ringloc)) > 0, "web: rc %d" % rc)


def bad_token(ringloc, paths_dir, tmp, ck):
    """A token that cannot travel in a cookie: one line, the poses all
    the same."""
    pty = Pty(tmp, "badtoken")
    cfg, n = config(tmp, paths_dir, "badtoken", pty.name, False,
                    "http: {listen: 127.0.0.1:%d, token: 'a b;c'}\n" % vl.free_port())
    rc = start(ringloc, cfg, tmp, "badtoken").wait(60)
    time.sleep(0.3)
    poses = pty.poses(ringloc)
    pty.close()
    lines = [ln for ln in err_of(tmp, "badtoken").splitlines() if "access token may hold" in ln]
    ck.check(rc == 0 and len(poses) == n and len(lines) == 1,
             "a token with a space and ';': rc %d, %d poses: %s" % (rc, len(poses), err_of(tmp, "badtoken")))


def main():
    ringloc, paths_dir, tmp = sys.argv[1:4]
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    ck = vl.Checks()
    port_taken(ringloc, paths_dir, tmp, ck)
    web_security(ringloc, paths_dir, tmp, ck)
    bad_token(ringloc, paths_dir, tmp, ck)
    ro = os.path.join(tmp, "rec_ro")
    os.makedirs(ro, exist_ok=True)
    if os.geteuid() == 0:
        ro = "/proc"  # root writes through a mode: a folder of a read-only file system
        expect = "/proc/drive_001"
    else:
        os.chmod(ro, 0o555)
        expect = "rec_ro/drive_001"
    no_drive(ringloc, paths_dir, tmp, ck, "rec_readonly", ro, expect)
    full = os.path.join(tmp, "rec_full")
    os.makedirs(full, exist_ok=True)
    for k in range(1, 1000):
        os.makedirs(os.path.join(full, "drive_%03d" % k), exist_ok=True)
    no_drive(ringloc, paths_dir, tmp, ck, "rec_999", full, "holds 999 drives")
    recording_stops(ringloc, paths_dir, tmp, ck)
    empty_drive(ringloc, paths_dir, tmp, ck)
    watchdog(ringloc, paths_dir, tmp, ck)
    return ck.done()


if __name__ == "__main__":
    vl.run(main)
