#!/usr/bin/env python3
"""The editor's first completion in a studio just started: what a student meets after `grcis studio scripts`.

For each build and round: start `grcis studio scripts --port 0 --no-open` (it warms the editor's language services in
the background), then, as a page that asks at once: the time from the start until the URL is printed, until
/api/status answers, until
/api/editor/ready answers (the services loaded: the editor bar stops saying "Loading code completion"), and the time
of the first and the second completion asked right after the status answered (a member of scripts/TwoSpheres.cs cut
after its first letter, the rest of the file after the caret), and when the first one's answer came after the URL was
printed (issue 39's measure: at most 1 s). Builds alternate round by round, so a changing load
touches them alike. Prints medians (and min, max) per build, the load average and the machine.

  bench/first-completion.py [ROUNDS] [LABEL=COMMAND ...]
      COMMAND: a grcis.dll (run with dotnet exec) or an executable such as an installed tool's grcis;
      default: 5 rounds of the Release build (built first)
"""
import json, os, re, statistics, subprocess, sys, threading, time, urllib.request

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 5
builds = [a.split("=", 1) for a in sys.argv[2:]]
if not builds:
    subprocess.run(["dotnet", "build", os.path.join(root, "src/GrCis.Cli"), "-c", "Release", "-v", "q", "-nologo"],
                   check=True, stdout=subprocess.DEVNULL)
    builds = [["build", os.path.join(root, "src/GrCis.Cli/bin/Release/net10.0/grcis.dll")]]

text = open(os.path.join(root, "scripts/TwoSpheres.cs"), encoding="utf-8").read()
# The fourth member access of the script, cut after its first letter; the rest of the file stays after the caret.
member = [m for m in re.finditer(r"(?<=[A-Za-z0-9_)\]]\.)[A-Za-z_]\w+", text)][3]
probe = text[:member.start() + 1] + text[member.end():]
caret = member.start() + 1


def once(command):
    argv = (["dotnet", "exec", command] if command.endswith(".dll") else [command]) + \
           ["studio", os.path.join(root, "scripts"), "--port", "0", "--no-open"]
    t0 = time.perf_counter()
    p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        url = p.stdout.readline().strip()
        printed = time.perf_counter() - t0
        base, token = url.split("/?token=")

        def call(method, path, body=None):
            req = urllib.request.Request(base + path, data=body and json.dumps(body).encode(), method=method,
                                         headers={"X-GrCis-Token": token, "Content-Type": "application/json"})
            with urllib.request.urlopen(req, timeout=300) as r:
                return r.read()

        while True:
            try:
                call("GET", "/api/status")
                break
            except OSError:
                time.sleep(0.01)
        answered = time.perf_counter() - t0
        ready = [None]

        def wait_ready():
            call("GET", "/api/editor/ready")
            ready[0] = time.perf_counter() - t0
        waiter = threading.Thread(target=wait_ready)
        waiter.start()
        t1 = time.perf_counter()
        call("POST", "/api/editor/complete", {"text": probe, "position": caret, "scene": "TwoSpheres"})
        first = time.perf_counter() - t1
        after_url = time.perf_counter() - t0 - printed
        t2 = time.perf_counter()
        call("POST", "/api/editor/complete", {"text": probe, "position": caret, "scene": "TwoSpheres"})
        second = time.perf_counter() - t2
        waiter.join()
        return printed, answered, ready[0], first, after_url, second
    finally:
        p.terminate()
        p.wait()


print(f"machine: {os.cpu_count()} cores, " +
      next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?"))
print(f"load average before: {open('/proc/loadavg').read().split()[:3]}")
results = {label: [] for label, _ in builds}
for _ in range(rounds):
    for label, command in builds:
        results[label].append(once(command))
names = ["URL printed", "status answered", "services ready", "first completion", "first answer - URL", "second completion"]
for label, runs in results.items():
    for i, name in enumerate(names):
        values = [r[i] for r in runs]
        print(f"{label:<10} {name:<20} median {statistics.median(values):6.3f} s  (min {min(values):.3f}, max {max(values):.3f}, "
              f"{len(values)} runs; times from the start except the completions' own)")
print(f"load average after: {open('/proc/loadavg').read().split()[:3]}")
