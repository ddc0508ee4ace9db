#!/usr/bin/env python3
"""The student's loop: the time from saving an edited scene script to its new PNG, three ways.

  watch   one `grcis render s.cs --watch` process; time from the save to its "wrote" line (the PNG is renamed
          into place before the line is printed)
  fresh   a new `grcis render s.cs` process after each save (what an IDE's "run" does); whole process time
  studio  one `grcis studio FOLDER` process (its saves write beside the script); time from `PUT /api/source` (the editor's save) until /api/status
          shows the render that save started as finished

Every round changes the script's text (the background colour), so each edit compiles anew; the compiled-script
cache is a fresh folder of this run (`GRCIS_CACHE_DIR`). 160x120, 1 spp, the FiveBalls scene. Prints the
median, min and max of each, the median CPU time (user + system) a save costs (steadier than wall time on a loaded
machine; the studio's includes its polled /api/status answers), the load average and the machine.

  bench/student-loop.py [ROUNDS] [path/to/grcis.dll] [WAYS]
      default: 10 rounds, the Release build (built first), WAYS watch,fresh,studio (a comma-separated choice, run
      in that order)
"""
import atexit, json, os, re, resource, shutil, statistics, subprocess, sys, tempfile, threading, time, urllib.request

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 10
dll = sys.argv[2] if len(sys.argv) > 2 else None
if dll is None:
    subprocess.run(["dotnet", "build", os.path.join(root, "src/GrCis.Cli"), "-c", "Release", "-v", "q", "-nologo"],
                   check=True, stdout=subprocess.DEVNULL)
    dll = os.path.join(root, "src/GrCis.Cli/bin/Release/net10.0/grcis.dll")
dll = os.path.abspath(dll)
work = tempfile.mkdtemp(prefix="grcis-loop-")
atexit.register(shutil.rmtree, work, ignore_errors=True)
env = dict(os.environ, GRCIS_CACHE_DIR=os.path.join(work, "cache"))
script = os.path.join(work, "s.cs")
base = open(os.path.join(root, "scripts/FiveBalls.cs"), encoding="utf-8").read()
size = ["--size", "160x120"]
counter = [0]


def edited():
    """The scene with a background no earlier round used, appended as its last statement."""
    counter[0] += 1
    return base + f"\nscene.BackgroundColor = new double[] {{ {counter[0] % 97 / 100.0:.2f}, 0.1, 0.2 }};\n"


def save(text):
    with open(script, "w", encoding="utf-8") as f:
        f.write(text)


def summary(name, times, cpu):
    return (f"{name:<7} median {statistics.median(times):.3f} s   (min {min(times):.3f}, max {max(times):.3f}, {len(times)} saves; "
            f"CPU per save: median {statistics.median(cpu):.3f} s)")


def cpu_of(pid):
    """User + system CPU seconds of a running process so far (Linux)."""
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def bench_watch():
    save(edited())
    p = subprocess.Popen(["dotnet", "exec", dll, "render", script, "-o", os.path.join(work, "w.png"), "-q", "--watch"] + size,
                         cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1)
    wrote = threading.Semaphore(0)
    threading.Thread(target=lambda: [wrote.release() for l in p.stdout if l.startswith("wrote ")], daemon=True).start()
    errors = []
    threading.Thread(target=lambda: [errors.append(l) for l in p.stderr], daemon=True).start()
    if not wrote.acquire(timeout=120):
        sys.exit("watch: no first image: " + "".join(errors))
    times, cpu = [], []
    for _ in range(rounds + 1):
        time.sleep(0.5)
        c0, t0 = cpu_of(p.pid), time.perf_counter()
        save(edited())
        if not wrote.acquire(timeout=120):
            sys.exit("watch: no image after a save: " + "".join(errors))
        times.append(time.perf_counter() - t0)
        cpu.append(cpu_of(p.pid) - c0)
    p.terminate()
    p.wait()
    return times[1:], cpu[1:]   # the first save after start-up still warms the compile path


def bench_fresh():
    times, cpu = [], []
    for _ in range(rounds):
        save(edited())
        c0, t0 = children_cpu(), time.perf_counter()
        subprocess.run(["dotnet", "exec", dll, "render", script, "-o", os.path.join(work, "f.png"), "-q"] + size,
                       cwd=work, env=env, check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
        cpu.append(children_cpu() - c0)
    return times, cpu


def bench_studio():
    save(edited())
    p = subprocess.Popen(["dotnet", "exec", dll, "studio", work, "--port", "0", "--no-open", "--nodefault"],
                         cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    url = p.stdout.readline().strip()
    base_url, token = url.split("/?token=")

    def call(method, path, body=None, content="application/json"):
        data = body.encode() if isinstance(body, str) else None
        req = urllib.request.Request(base_url + path, data=data, method=method,
                                     headers={"X-GrCis-Token": token, "Content-Type": content})
        with urllib.request.urlopen(req, timeout=120) as r:
            text = r.read().decode()
            return json.loads(text) if text and r.headers.get_content_type() == "application/json" else None

    def finished(after):
        while True:
            s = call("GET", "/api/status")
            if s["renderId"] > after and not s["rendering"] and s["phase"] == "idle":
                return s
            time.sleep(0.005)

    scene = next(x["name"] for x in call("GET", "/api/scenes")["scenes"] if x.get("file") == "s.cs")
    settings = call("GET", "/api/settings")
    settings.update(width=160, height=120, samplesPerPixel=1)
    started = call("POST", "/api/render", json.dumps({"scene": scene, "settings": settings, "given": ["Size"]}))
    last = finished(started["renderId"] - 1)["renderId"]
    times, cpu = [], []
    for _ in range(rounds + 1):
        time.sleep(0.5)
        c0, t0 = cpu_of(p.pid), time.perf_counter()
        call("PUT", "/api/source?scene=" + urllib.parse.quote(scene), edited(), "text/plain; charset=utf-8")
        s = finished(last)
        times.append(time.perf_counter() - t0)
        cpu.append(cpu_of(p.pid) - c0)
        if s.get("error"):
            sys.exit("studio: " + str(s["error"]))
        last = s["renderId"]
    p.terminate()
    p.wait()
    return times[1:], cpu[1:]


import urllib.parse  # noqa: E402  (used by bench_studio)

print(f"grcis: {dll}")
print(f"machine: {os.cpu_count()} cores, " +
      next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?"))
print(f"load average before: {open('/proc/loadavg').read().split()[:3]}")
ways = {"watch": bench_watch, "fresh": bench_fresh, "studio": bench_studio}
chosen = sys.argv[3].split(",") if len(sys.argv) > 3 else list(ways)
results = {name: ways[name]() for name in chosen}
for name, (times, cpu) in results.items():
    print(summary(name, times, cpu))
print(f"load average after: {open('/proc/loadavg').read().split()[:3]}")
