"""The package's layout: every module, in any subpackage, is in the source hash that keys the Numba cache."""

import shutil

import pytest

import sphgag
from sphgag import _source_hash

PACKAGE = sphgag._PACKAGE_DIR
MODULES = sorted(p.relative_to(PACKAGE).as_posix() for p in PACKAGE.rglob("*.py"))


@pytest.fixture(scope="module")
def package_copy(tmp_path_factory):
    dest = tmp_path_factory.mktemp("package") / "sphgag"
    shutil.copytree(PACKAGE, dest, ignore=shutil.ignore_patterns("__pycache__"))
    return dest


def test_the_hash_is_the_packages_own():
    assert sphgag.CODE_HASH == _source_hash()


@pytest.mark.parametrize("module", MODULES)
def test_an_edit_of_any_module_changes_the_source_hash(package_copy, module):
    before = _source_hash(package_copy)
    path = package_copy / module
    original = path.read_bytes()
    try:
        path.write_bytes(original + b"# a comment\n")
        assert _source_hash(package_copy) != before, module
    finally:
        path.write_bytes(original)
    assert _source_hash(package_copy) == before


def test_a_new_module_in_a_new_subpackage_changes_the_source_hash(package_copy):
    before = _source_hash(package_copy)
    extra = package_copy / "new_subpackage" / "law.py"
    extra.parent.mkdir()
    extra.write_text("X = 1\n")
    try:
        assert _source_hash(package_copy) != before
    finally:
        shutil.rmtree(extra.parent)


LAYERS = ["physics", "engine", "records", "studies", "views"]  # each imports only the layers before it


def _imports(path):
    """The subpackages of sphgag a module imports (relative imports resolved)."""
    import ast

    rel = path.relative_to(PACKAGE).parts
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            if node.level:  # relative: resolve against the module's package
                base = list(rel[:-1])[: len(rel) - node.level]
                parts = base + (node.module.split(".") if node.module else [])
                names = [parts + [a.name] for a in node.names] if not node.module else [parts]
            elif (node.module or "").startswith("sphgag"):
                names = [node.module.split(".")[1:]]
            else:
                continue
            out |= {n[0] for n in names if n and n[0] in LAYERS}
    return out


@pytest.mark.parametrize("module", [m for m in MODULES if m.split("/")[0] in LAYERS])
def test_a_layer_imports_only_the_layers_before_it(module):
    layer = module.split("/")[0]
    allowed = set(LAYERS[: LAYERS.index(layer) + 1])
    assert _imports(PACKAGE / module) <= allowed, module
