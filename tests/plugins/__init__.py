"""Variants written by a contributor, one file each, registered by :mod:`tests.test_registry` for a test only: a new
pool model, a new damage law and a new hourglass form (docs/contributing.md, "Variants")."""
