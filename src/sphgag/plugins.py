"""Variants of one's own, from the configuration alone: the files of the key ``plugins``.

A plug-in is one Python file (a path relative to the working directory) that defines a variant of one kind and names
it: ``REGISTRY``, the registry of its kind (e.g. :data:`sphgag.physics.damage.DAMAGE_LAWS`), and ``VARIANT``, the new
variant (docs/contributing.md, "Variants"). :func:`load` registers each; the Snakefile loads them before it validates
the configuration, so that the schema's enumerations name them, and exports them in :data:`ENVIRONMENT`, from which
every job loads them again (:func:`sphgag.jobs.run`): a job is a process of its own. A plug-in's file is a code input
of the jobs that may compute with its variant (workflow/rules/common.smk, ``code_of``): those whose wildcards name it
(a charge law, pool model, hourglass form or sensitivity method runs as jobs of its own), and, for a variant a
setting selects (a damage law, the hourglass form), those whose scripts import the module that builds it from the
settings. An edit of the file reruns those jobs, and nothing else.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
from pathlib import Path

#: the environment variable that carries the plug-in files to the jobs (``os.pathsep``-separated paths)
ENVIRONMENT = "SPHGAG_PLUGINS"


def load(paths) -> list:
    """Import each file of ``paths`` once and register its ``VARIANT`` in its ``REGISTRY`` (ValueError naming the file
    where it defines neither). Returns the modules."""
    modules = []
    for path in map(Path, paths):
        name = _module_name(path)
        spec = importlib.util.spec_from_file_location(name, path)
        if spec is None or not path.is_file():
            raise ValueError(f"plugins: {path} is no Python file")
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module  # as an import does: dataclasses and typing look the module up by its name
        spec.loader.exec_module(module)
        if not (hasattr(module, "REGISTRY") and hasattr(module, "VARIANT")):
            raise ValueError(f"plugins: {path} defines no REGISTRY and VARIANT (docs/contributing.md, 'Variants')")
        if module.VARIANT.name not in module.REGISTRY:
            module.REGISTRY.register(module.VARIANT)
        modules.append(module)
    return modules


def _module_name(path: Path) -> str:
    """The name a plug-in file's module is loaded under (one per file)."""
    return f"sphgag_plugin_{hashlib.sha256(str(path.resolve()).encode()).hexdigest()[:12]}"


def variant_of(path) -> tuple:
    """``(registry, name)`` of the plug-in in the file ``path``: the registry of its kind and its variant's name (the
    module :func:`export` loaded, else the file loaded now)."""
    module = sys.modules.get(_module_name(Path(path))) or load([path])[0]
    return module.REGISTRY, module.VARIANT.name


def export(paths) -> None:
    """Load ``paths`` here and hand them to every job of this workflow (:data:`ENVIRONMENT`); a value that is no list
    is left to the configuration's check, which names it."""
    if not isinstance(paths, list | tuple):
        return
    load(paths)
    os.environ[ENVIRONMENT] = os.pathsep.join(str(Path(p).resolve()) for p in paths)


def load_exported() -> None:
    """Load the plug-ins the workflow exported (:func:`export`), in a job's process."""
    load(filter(None, os.environ.get(ENVIRONMENT, "").split(os.pathsep)))
