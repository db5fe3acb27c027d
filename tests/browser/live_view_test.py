#!/usr/bin/env python3
"""The live view in a real browser (Debian's chromium, headless, through chromium-driver
and python3-selenium): tridem run --live serves the page; the canvas shows particles;
frames keep arriving; pause holds the step counter, single step adds one, resume goes on;
garbage and oversized messages on the WebSocket are survived; the run ends normally when
the browser goes mid-run.

usage: live_view_test.py TRIDEM SOURCE_DIR WORK_DIR [SCREENSHOT.png]
Exits 77 (CTest's skip) with the reason when chromium, its driver or selenium is missing.
"""
import os
import shutil
import socket
import subprocess
import sys
import time

SKIP = 77


def skip(why):
    print(f"SKIP: {why}")
    sys.exit(SKIP)


try:
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:
    skip("python3-selenium is not installed (apt-get install python3-selenium)")

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
DRIVER = shutil.which("chromedriver")
if not CHROMIUM or not DRIVER:
    skip("chromium and chromium-driver are not installed (apt-get install chromium chromium-driver)")

tridem, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
screenshot = sys.argv[4] if len(sys.argv) > 4 else None
os.makedirs(work, exist_ok=True)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print(f"ok: {what}")


port = free_port()
log_path = os.path.join(work, "run.log")
log = open(log_path, "w")
run = subprocess.Popen(
    [tridem, "run", os.path.join(source, "tests/browser/live_scene.toml"), "--out",
     os.path.join(work, "out"), "--quiet", "--live", str(port), "--live-paused"],
    stdout=log, stderr=subprocess.STDOUT)


def run_log():
    log.flush()
    with open(log_path) as f:
        return f.read()


def wait_for(what, condition, timeout=20):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for {what}\n--- tridem's log ---\n{run_log()}")


driver = None
try:
    wait_for("the live view's address", lambda: "live view on" in run_log() or run.poll() is not None)
    check(run.poll() is None, "tridem run --live is serving")
    options = Options()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                 "--window-size=1000,700", "--disable-gpu-sandbox"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
    driver.set_script_timeout(10)
    driver.get(f"http://127.0.0.1:{port}/")
    js = driver.execute_script
    WebDriverWait(driver, 20).until(lambda d: js("return window.tridemLive && tridemLive.frames > 0"))
    errors = js("return tridemLive.errors")
    check(not errors, f"the page runs WebGL2 (errors: {errors})")
    check(js("return tridemLive.n") == 45, "the geometry of 45 triangles arrived")

    # Paused after the first step (--live-paused): the counter holds.
    WebDriverWait(driver, 10).until(lambda d: js("return tridemLive.paused"))
    held = js("return tridemLive.step")
    frames = js("return tridemLive.frames")
    WebDriverWait(driver, 10).until(lambda d: js("return tridemLive.frames") >= frames + 5)
    check(js("return tridemLive.step") == held, f"paused: frames keep arriving, step stays {held}")

    # The canvas: a free grain's centroid is drawn in a colour of the map, not background
    # and not the walls' grey; a wall's centroid is grey.
    background = js("return tridemLive.background()")
    free = [i for i in range(45) if js("return tridemLive.isFree(arguments[0])", i)]
    wall = [i for i in range(45) if i not in free]
    coloured = 0
    for i in free[:10]:
        p = js("return tridemLive.probe(arguments[0])", i)
        if max(abs(p[k] - background[k]) for k in range(3)) > 30 and not (abs(p[0] - p[1]) < 8 and abs(p[1] - p[2]) < 8):
            coloured += 1
    check(coloured >= 9, f"{coloured} of 10 grains' centroids show a colour of the map (background {background})")
    g = js("return tridemLive.probe(arguments[0])", wall[0])
    check(abs(g[0] - 140) < 20 and abs(g[0] - g[2]) < 12, f"a wall's centroid is grey ({g})")
    if screenshot:
        driver.save_screenshot(screenshot)

    # Single step: exactly one step more, then held again.
    js("tridemLive.send('step')")
    WebDriverWait(driver, 10).until(lambda d: js("return tridemLive.step") == held + 1)
    check(True, f"single step: {held} -> {held + 1}")

    # Garbage from a second client: unknown text, binary, a bad number, an oversized
    # message. The run and the first page carry on.
    js("""
      const w = new WebSocket(`ws://${location.host}/ws`);
      w.binaryType = 'arraybuffer';
      w.onopen = () => {
        w.send('hello?'); w.send(new Uint8Array([0, 255, 7, 1]).buffer); w.send('fps 0');
        w.send('x'.repeat(1000)); w.send('y'.repeat(200000));
      };
      window.garbageClosed = false; w.onclose = () => { window.garbageClosed = true; };
    """)
    WebDriverWait(driver, 10).until(lambda d: js("return window.garbageClosed"))
    text = run_log()
    check("unknown command 'hello?'" in text, "garbage text dropped with a log line")
    check("binary message of 4 bytes dropped" in text, "binary message dropped with a log line")
    check("fps wants a whole number" in text, "bad fps dropped with a log line")
    check("message of 1000 bytes" in text, "long message dropped with a log line")
    check("message over 65536 bytes: connection closed" in text, "oversized message closes that connection")

    # Resume (the page's button): frames of later steps arrive; pause (the button) again at
    # once, before this short run can end.
    driver.find_element("id", "resume").click()
    WebDriverWait(driver, 20).until(lambda d: js("return tridemLive.step") > held + 20)
    driver.find_element("id", "pause").click()
    check(True, f"resumed: a frame of step {js('return tridemLive.step')} arrived")
    WebDriverWait(driver, 20).until(lambda d: js("return tridemLive.paused"))
    f0 = js("return tridemLive.frames")
    WebDriverWait(driver, 20).until(lambda d: js("return tridemLive.frames") >= f0 + 3)
    s0 = js("return tridemLive.step")
    WebDriverWait(driver, 20).until(lambda d: js("return tridemLive.frames") >= f0 + 6)
    check(js("return tridemLive.step") == s0 and s0 < 40000 and not js("return tridemLive.ended"),
          f"paused again at step {s0}, mid-run")
finally:
    if driver:
        driver.quit()  # the browser goes while the run is paused mid-way

try:
    rc = run.wait(timeout=60)
except subprocess.TimeoutExpired:
    run.kill()
    raise AssertionError(f"the run did not end after the browser left\n{run_log()}")
text = run_log()
check(rc == 0, f"the run ended normally after the browser left (exit status {rc})")
check("the last client has gone: the run resumes" in text, "the run resumed without its browser")
check("done: " in text, "the run reached its last step")
print("PASS")
