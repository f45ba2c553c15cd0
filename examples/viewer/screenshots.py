#!/usr/bin/env python3
"""Redraws docs/viewer.png, the viewer's screenshot in README.md and
docs/viewer.md, with the browser harness of the viewer's test
(bindings/python/tests/viewer_harness.py: headless chromium, chromedriver,
python3-selenium). From the repository root, after a build:

    HDT_LIBRARY=build/lib/libhdt.so.0 PYTHONPATH=bindings/python \\
        /usr/bin/python3 examples/viewer/screenshots.py [OUT.png]

The page: 1000 random points of M_2 (seed 5, uniform for area), the Voronoi diagram on, the
view dragged across a side of F_g so that the copies beyond it come in, and
the pointer over a vertex (the panel names it).
"""
import math
import os
import random
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "bindings", "python", "tests"))

import hdt  # noqa: E402
import viewer_harness  # noqa: E402


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "docs", "viewer.png")
    missing = viewer_harness.missing()
    if missing:
        sys.exit("examples/viewer/screenshots.py: " + missing)
    # Uniform for hyperbolic area in F_g: uniform in a disk about 0 that
    # holds F_g, kept when in F_g (its representative is itself).
    rng = random.Random(5)
    points, rho = [], 2 * math.atanh(0.85)
    while len(points) < 1000:
        d = math.acosh(1 + rng.random() * (math.cosh(rho) - 1))
        r, a = math.tanh(d / 2), 2 * math.pi * rng.random()
        z = (r * math.cos(a), r * math.sin(a))
        if hdt.point_representative(2, *z)[1] == ():
            points.append(z)
    t = hdt.Triangulation(2)
    t.insert_many(points)
    t.remove_dummies()
    from selenium.webdriver.common.actions.action_builder import ActionBuilder
    from selenium.webdriver.common.by import By

    driver = viewer_harness.browser((1000, 700))
    try:
        with tempfile.TemporaryDirectory() as tmp:
            page = os.path.join(tmp, "viewer.html")
            t.to_html(page, voronoi=True)
            viewer_harness.open_page(driver, page)
            driver.find_element(By.ID, "hdt-voronoi").click()
            view = driver.execute_script("return window.hdtViewer.view()")
            x0, y0 = round(view["cx"]), round(view["cy"])
            actions = ActionBuilder(driver)
            actions.pointer_action.move_to_location(x0 + 60, y0).pointer_down()
            actions.pointer_action.move_to_location(x0 - 60, y0 + 30).pointer_up()
            actions.perform()
            viewer_harness.settle(driver)
            vertex = t.nearest_vertex(0.0, 0.0)
            x, y = driver.execute_script("return window.hdtViewer.screenPosition(arguments[0])", vertex)
            actions = ActionBuilder(driver)
            actions.pointer_action.move_to_location(round(x), round(y))
            actions.perform()
            viewer_harness.settle(driver)
            errors = viewer_harness.severe_log(driver)
            if errors:
                sys.exit("the page logged errors: %r" % errors)
            with open(out, "wb") as file:
                file.write(driver.get_screenshot_as_png())
    finally:
        driver.quit()
    print("wrote", out)


if __name__ == "__main__":
    main()
