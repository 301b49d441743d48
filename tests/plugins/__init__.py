"""Variants written by a contributor, one file each (a module naming ``REGISTRY`` and ``VARIANT``): a charge law, a
damage law, a pool model, an hourglass form and a sensitivity method (docs/contributing.md, "Variants"). The unit tests
register them for a test only; tests/test_plugins.py names them in the configuration's key ``plugins`` and runs them
through the pipeline's jobs."""
