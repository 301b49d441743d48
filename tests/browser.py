"""Headless Chromium through Selenium, for tests/test_browser.py: what a real browser loads of a page's images."""

import importlib.util
from pathlib import Path

import pytest
from PIL import Image

CHROMIUM, CHROMEDRIVER = Path("/usr/bin/chromium"), Path("/usr/bin/chromedriver")
# what the browser reports of one image (an <img> of the page, or one that load_images made)
DESCRIBE = "i => ({src: i.src, complete: i.complete, naturalWidth: i.naturalWidth, naturalHeight: i.naturalHeight})"
# load every <img> now (lazy ones too): true once the page and all its images have loaded or failed
SETTLED = """Array.from(document.images, i => { i.loading = "eager"; });
return document.readyState === "complete" && Array.from(document.images).every(i => i.complete);"""
# new Image() for each of the URIs arguments[0] (resolved against the page's URL), reported once each has loaded
# or failed
LOAD = f"""const [uris, done] = arguments;
Promise.all(uris.map(uri => new Promise(resolve => {{
    const image = new Image();
    image.onload = image.onerror = () => resolve(({DESCRIBE})(image));
    image.src = new URL(uri, document.baseURI).href;
}}))).then(done);"""


def missing() -> str | None:
    """Why no browser can run here (Chromium, its WebDriver or Selenium missing), or None."""
    for program in (CHROMIUM, CHROMEDRIVER):
        if not program.is_file():
            return f"no {program} (apt-get install chromium chromium-driver)"
    return None if importlib.util.find_spec("selenium") else "no selenium (pip install -r environment.txt)"


def chromium_driver(width: int = 1280, height: int = 1600):
    """A headless Chromium (Debian's chromium and chromium-driver) driven by Selenium, or ``pytest.skip`` with the
    reason when one of them is missing."""
    if reason := missing():
        pytest.skip(reason)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"):
        options.add_argument(argument)
    options.add_argument(f"--window-size={width},{height}")
    options.add_argument("--host-resolver-rules=MAP * ~NOTFOUND")  # offline: the pages load from files only
    driver = webdriver.Chrome(service=Service(str(CHROMEDRIVER)), options=options)
    driver.set_page_load_timeout(120)
    driver.set_script_timeout(120)
    return driver


def page_images(driver, url: str, screenshot_path, timeout: float = 60) -> list[dict]:
    """Open ``url``, wait (polling, at most ``timeout`` s) until every ``<img>`` of the page has loaded or failed,
    save a screenshot to ``screenshot_path``, and return ``src``, ``complete``, ``naturalWidth`` and
    ``naturalHeight`` of each ``<img>`` as the browser reports them."""
    from selenium.webdriver.support.ui import WebDriverWait

    driver.get(url)
    WebDriverWait(driver, timeout, poll_frequency=0.2).until(lambda d: d.execute_script(SETTLED))
    assert driver.save_screenshot(str(screenshot_path)), screenshot_path
    return driver.execute_script(f"return Array.from(document.images, {DESCRIBE});")


def load_images(driver, uris: list[str]) -> list[dict]:
    """Load each URI (relative ones against the open page's URL) with ``new Image()`` in the page and return what
    the browser reports of it once it has loaded or failed (as ``page_images``), in the same order."""
    return driver.execute_async_script(LOAD, list(uris))


def one_colour(png) -> bool:
    """Whether every pixel of the image file ``png`` has the same colour (a blank screenshot)."""
    with Image.open(png) as image:
        return image.convert("RGB").getcolors(1) is not None


def loaded(images: list[dict]) -> list[dict]:
    """The images (as ``page_images`` reports them) that loaded: complete and with a nonzero natural size."""
    return [i for i in images if i["complete"] and i["naturalWidth"] > 0 and i["naturalHeight"] > 0]
