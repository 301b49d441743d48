"""The package modules a workflow script's job runs: the code input of the rule that runs the script.

Snakemake tracks a rule's script, not the modules the script imports. A rule's code input is therefore computed from
the imports: the script is parsed and every ``import``/``from ... import`` of the package (absolute, or relative
inside the package) is followed through the package, transitively, with the ``__init__.py`` of every package on the
way (importing ``sphgag.a.b`` runs ``sphgag/__init__.py`` and ``sphgag/a/__init__.py`` first). The whole syntax tree
is read, so that an import inside a function counts as much as one at the top of a module. An edit of a module then
reruns exactly the jobs that import it, and a module no script imports is the input of no job.

Two kinds of module are followed but are inputs of nothing, because they compute no number:

- the modules that run no code, a docstring alone (most ``__init__.py`` of the subpackages);
- :data:`BOOKKEEPING`, the modules that only set up a job or record it.

Loaded by workflow/rules/common.smk (``code_of``), and by the tests.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

# The job's bookkeeping: the package's root (version, and the Numba cache's location keyed by the sources' hash),
# the job layer (its kinds' run keys, which name the files, and the set-up of a job: threads, log, typed wildcards),
# the plug-ins' loader (each plug-in's file is a code input of its own), the threads a job computes on, its log and
# its provenance record. None of them changes a number a job writes.
BOOKKEEPING = frozenset(
    {
        "__init__.py",
        "jobs/__init__.py",
        "jobs/kinds.py",
        "plugins.py",
        "threads.py",
        "records/runlog.py",
        "records/provenance.py",
    }
)


class Package:
    """The modules of the package in the directory ``root`` (its name is the directory's: ``src/sphgag``)."""

    def __init__(self, root: Path):
        self.root = Path(root)
        self.name = self.root.name
        self._imported = {}  # {file: imported(file)}: each module parsed once

    def file(self, module: str) -> Path | None:
        """The file of the dotted ``module`` (``sphgag.a.b``: ``a/b.py`` or ``a/b/__init__.py``), None if it is no
        module of the package (a name defined in a module, or another package)."""
        head, *parts = module.split(".")
        if head != self.name:
            return None
        path = self.root.joinpath(*parts)
        for candidate in (path / "__init__.py", path.with_suffix(".py")):
            if candidate.is_file():
                return candidate
        return None

    def dotted(self, path: Path) -> str:
        """The dotted name of the module in ``path``."""
        parts = path.relative_to(self.root).with_suffix("").parts
        return ".".join((self.name, *(parts[:-1] if parts[-1] == "__init__" else parts)))

    def imported(self, path: Path) -> frozenset[str]:
        """The modules of the package that the file ``path`` (a module of the package or a script) imports directly,
        as dotted names, with every package on the way (the ``__init__.py`` files an import runs)."""
        if path not in self._imported:
            self._imported[path] = self._parse(path)
        return self._imported[path]

    def _parse(self, path: Path) -> frozenset[str]:
        tree = ast.parse(path.read_text(), filename=str(path))
        inside = self.root in path.parents
        here = self.dotted(path) if inside else ""
        # relative imports resolve against the module's package (a package's own name for its __init__.py)
        package = here if inside and path.name == "__init__.py" else here.rpartition(".")[0]
        modules = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                modules.update(alias.name for alias in node.names)
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
                    source = f"{base}.{node.module}" if node.module else base
                else:
                    source = node.module
                modules.add(source)
                # `from a import b`: b is a module of its own where it is one
                modules.update(f"{source}.{alias.name}" for alias in node.names)
        ran = {".".join(m.split(".")[: i + 1]) for m in modules for i in range(m.count(".") + 1)}
        return frozenset(m for m in ran if self.file(m) is not None)

    def modules(self, script: Path) -> list[str]:
        """The modules (paths relative to the package) that running ``script`` imports, transitively, less those
        that compute no number: the code input of the rule that runs it."""
        seen, todo = set(), [Path(script)]
        while todo:
            for module in self.imported(todo.pop()):
                if module not in seen:
                    seen.add(module)
                    todo.append(self.file(module))
        paths = (self.file(m) for m in seen)
        names = {p.relative_to(self.root).as_posix(): p for p in paths}
        return sorted(name for name, p in names.items() if name not in BOOKKEEPING and not docstring_only(p))


@functools.cache
def docstring_only(path: Path) -> bool:
    """Whether the module in ``path`` runs no code: its body is a docstring alone (or nothing)."""
    body = ast.parse(path.read_text()).body
    return all(isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) for node in body)


def code_inputs(scripts: Path, package: Path) -> dict[str, list[str]]:
    """``{script name: its modules}`` (:meth:`Package.modules`) for every script ``*.py`` in the directory
    ``scripts``; the modules as paths relative to the package directory ``package``."""
    pkg = Package(package)
    return {script.stem: pkg.modules(script) for script in sorted(Path(scripts).glob("*.py"))}
