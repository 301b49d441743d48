"""Logging for pipeline scripts: progress to the rule's log file, failures named clearly."""

from __future__ import annotations

import logging
import sys
import time
from contextlib import contextmanager


def setup(log_path=None, level=logging.INFO) -> logging.Logger:
    """Send the ``sphgag`` logger to ``log_path`` (if given) and to stderr, line by line.

    With a log file, the progress (every converged state) goes to the file only and the terminal gets
    warnings and errors, so that a Snakemake run shows its job progress, not thousands of states.
    """
    logger = logging.getLogger("sphgag")
    logger.setLevel(level)
    logger.handlers.clear()
    fmt = logging.Formatter("%(asctime)s %(levelname)s %(message)s", "%H:%M:%S")
    terminal = logging.StreamHandler(sys.stderr)
    handlers = [terminal]
    if log_path:
        terminal.setLevel(logging.WARNING)
        handlers.append(logging.FileHandler(log_path, mode="w"))
    for h in handlers:
        h.setFormatter(fmt)
        logger.addHandler(h)
    logger.propagate = False
    return logger


@contextmanager
def run(name: str, log_path=None):
    """Context for one pipeline step: logs start, wall time and any failure (then re-raises)."""
    logger = setup(log_path)
    started = time.time()
    logger.info("[%s] started", name)
    try:
        yield logger
    except Exception as exc:
        logger.error("[%s] FAILED: %s: %s", name, type(exc).__name__, exc)
        raise
    logger.info("[%s] finished in %.1f s", name, time.time() - started)
