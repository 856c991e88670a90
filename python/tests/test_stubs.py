"""The type stubs cover the API: every name hsx exports is in __init__.pyi, and every public attribute of the
extension's classes is in _hsx.pyi (so editors complete what exists)."""
import ast
import inspect
import pathlib

import hsx
from hsx import _hsx

PACKAGE = pathlib.Path(hsx.__file__).parent


def stub_names(path):
    tree = ast.parse(path.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            names = set()
            for item in node.body:
                if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    names.add(item.name)
                elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                    names.add(item.target.id)
            members[node.name] = names
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            top.add(node.target.id)
        elif isinstance(node, ast.ImportFrom):
            top.update(a.asname or a.name for a in node.names)
    return top, members


def test_package_stub_lists_every_export():
    top, _ = stub_names(PACKAGE / "__init__.pyi")
    assert set(hsx.__all__) - top == set()


def test_extension_stub_lists_every_member():
    top, members = stub_names(PACKAGE / "_hsx.pyi")
    missing = []
    for name, obj in vars(_hsx).items():
        if name.startswith("_") or not inspect.isclass(obj) or issubclass(obj, BaseException):
            continue
        assert name in top, name
        for attr in dir(obj):
            if attr.startswith("_") or attr in ("name", "value"):
                continue
            if attr not in members[name] and not (name == "Order" and attr in obj.__members__):
                missing.append(f"{name}.{attr}")
    assert missing == []
