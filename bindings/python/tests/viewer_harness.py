"""A headless browser for the viewer's page (hdt.viewer): Debian 12's
chromium, chromedriver and python3-selenium. Used by test_viewer.py and by
examples/viewer/screenshots.py, which makes docs/viewer.png with it.

missing() says what is not installed (None when all is); browser() starts
chromium headless, as root too (--no-sandbox), with a fixed window and a
device pixel ratio of 1, so that canvas pixels are CSS pixels.
"""

import os
import shutil

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")
WINDOW = (1100, 760)

# The page's pixels, counted in the browser: "ink" (dark enough to be a
# line or a dot: the shaded F_g and the disk are not), Voronoi green
# (#2a8a3a) and dummy red (#d62728).
COUNT_PIXELS = """
var canvas = document.getElementById("hdt-canvas");
var d = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
var ink = 0, green = 0, red = 0;
for (var i = 0; i < d.length; i += 4) {
  var r = d[i], g = d[i + 1], b = d[i + 2];
  if (Math.min(r, g, b) < 180) ++ink;
  if (g > r + 40 && g > b + 30) ++green;
  if (r > 180 && g < 80 && b < 80) ++red;
}
return {ink: ink, green: green, red: red};
"""


def chromium():
    for name in CHROMIUM_NAMES:
        path = shutil.which(name)
        if path:
            return path
    return None


def missing():
    """None when the browser can run, else what is missing (a sentence)."""
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "python3-selenium is not installed (apt-get install python3-selenium)"
    if chromium() is None:
        return "chromium is not installed (apt-get install chromium)"
    if shutil.which("chromedriver") is None:
        return "chromedriver is not installed (apt-get install chromium-driver)"
    return None


def browser(window=WINDOW):
    """A headless chromium under selenium, its console log kept."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = chromium()
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--force-device-scale-factor=1",
                     "--window-size=%d,%d" % window, "--disable-extensions", "--no-first-run"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    # Not the sanitizer runtimes .ci/sanitize preloads into python for libhdt:
    # the browser is no part of what it checks.
    env = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS", "UBSAN_OPTIONS")}
    return webdriver.Chrome(service=Service(shutil.which("chromedriver"), env=env), options=options)


def open_page(driver, path):
    """Loads the page file (from disk, file://) and waits for its hook."""
    import time

    driver.get("file://" + os.path.abspath(path))
    deadline = time.time() + 20
    while not driver.execute_script("return !!window.hdtViewer") and time.time() < deadline:
        time.sleep(0.05)
    settle(driver)


def settle(driver):
    """Waits until the page has drawn what was asked (two animation frames)."""
    driver.execute_async_script(
        "var done = arguments[0]; requestAnimationFrame(function () { requestAnimationFrame(function () { done(); }); });")


def pixels(driver):
    return driver.execute_script(COUNT_PIXELS)


def severe_log(driver):
    """The console's errors (and the page's uncaught exceptions) since the last call."""
    return [entry for entry in driver.get_log("browser") if entry.get("level") == "SEVERE"]
