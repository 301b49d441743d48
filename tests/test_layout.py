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
