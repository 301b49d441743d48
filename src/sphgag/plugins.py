"""Variants of one's own, from the configuration alone: the files of the key ``plugins``.

A plug-in is one Python file (a path relative to the working directory) that defines a variant of one kind and names
it: ``REGISTRY``, the registry of its kind (e.g. :data:`sphgag.physics.damage.DAMAGE_LAWS`), and ``VARIANT``, the new
variant (docs/contributing.md, "Variants"). :func:`load` registers each; the Snakefile loads them before it validates
the configuration, so that the schema's enumerations name them, and exports them in :data:`ENVIRONMENT`, from which
every job loads them again (:func:`sphgag.jobs.run`): a job is a process of its own. A plug-in's file is a code input
of every job whose script imports the module of its kind (:func:`kind_module`; workflow/rules/common.smk), so an edit
of it reruns what may compute with it, and nothing else.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
from pathlib import Path

#: the environment variable that carries the plug-in files to the jobs (``os.pathsep``-separated paths)
ENVIRONMENT = "SPHGAG_PLUGINS"


def load(paths) -> list:
    """Import each file of ``paths`` once and register its ``VARIANT`` in its ``REGISTRY`` (ValueError naming the file
    where it defines neither). Returns the modules."""
    modules = []
    for path in map(Path, paths):
        name = f"sphgag_plugin_{hashlib.sha256(str(path.resolve()).encode()).hexdigest()[:12]}"
        spec = importlib.util.spec_from_file_location(name, path)
        if spec is None or not path.is_file():
            raise ValueError(f"plugins: {path} is no Python file")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        if not (hasattr(module, "REGISTRY") and hasattr(module, "VARIANT")):
            raise ValueError(f"plugins: {path} defines no REGISTRY and VARIANT (docs/contributing.md, 'Variants')")
        if module.VARIANT.name not in module.REGISTRY:
            module.REGISTRY.register(module.VARIANT)
        modules.append(module)
    return modules


def kind_module(path) -> str:
    """The module (its path in the package, ``physics/damage.py``) that defines the kind of the plug-in in the file
    ``path``: that of the first class of the package its variant is, or is an instance of, a subclass of."""
    (module,) = load([path])
    variant = module.VARIANT if isinstance(module.VARIANT, type) else type(module.VARIANT)
    home = next(c.__module__ for c in variant.__mro__ if c.__module__.startswith("sphgag."))
    return "/".join(home.split(".")[1:]) + ".py"


def export(paths) -> None:
    """Load ``paths`` here and hand them to every job of this workflow (:data:`ENVIRONMENT`)."""
    load(paths)
    os.environ[ENVIRONMENT] = os.pathsep.join(str(Path(p).resolve()) for p in paths)


def load_exported() -> None:
    """Load the plug-ins the workflow exported (:func:`export`), in a job's process."""
    load(filter(None, os.environ.get(ENVIRONMENT, "").split(os.pathsep)))
