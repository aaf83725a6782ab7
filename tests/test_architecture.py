"""The import rules of docs/ARCHITECTURE.md: which package may import which, and no import
circle between modules — imports inside functions included (they hide circles, not remove
them)."""
import ast
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("contact", "exudyn_bearing")
#: what each package may import beyond the standard library (top-level names)
ALLOWED = {
    "contact": {"contact", "numpy", "scipy", "numba", "llvmlite"},
    "exudyn_bearing": {"exudyn_bearing", "contact", "exudyn", "numpy", "scipy", "numba", "matplotlib", "dask",
                       "tomli", "PIL", "imageio"},
}


def _module(path):
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path):
    """(top-level name, module) of every import in the file, at any depth of the syntax tree."""
    mod = _module(path)
    package = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module
            for alias in node.names:  # "from pkg import submodule" imports the submodule
                sub = f"{target}.{alias.name}"
                out.append(sub if (ROOT / Path(*sub.split("."))).with_suffix(".py").exists() else target)
    return out


def _graph():
    graph = {}
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            graph[_module(path)] = {m for m in _imports(path) if m.split(".")[0] in PACKAGES} - {_module(path)}
    return graph


def _cycles(graph):
    """Strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in graph:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    sys.setrecursionlimit(max(sys.getrecursionlimit(), 5000))
    for v in list(graph):
        if v not in index:
            visit(v)
    return found


def test_no_import_circle():
    assert _cycles(_graph()) == []


def test_the_cycle_finder_sees_a_circle():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


def test_function_level_imports_are_seen(tmp_path, monkeypatch):
    """A circle made only by an import inside a function is still a circle."""
    pkg = tmp_path / "exudyn_bearing"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from .b import f\n")
    (pkg / "b.py").write_text("def f():\n    from .a import g\n")
    monkeypatch.setattr(sys.modules[__name__], "ROOT", tmp_path)
    monkeypatch.setattr(sys.modules[__name__], "PACKAGES", ("exudyn_bearing",))
    assert _cycles(_graph()) == [["exudyn_bearing.a", "exudyn_bearing.b"]]


def test_packages_import_only_what_the_architecture_allows():
    stdlib = set(sys.stdlib_module_names) | {"__future__"}
    bad = []
    for package, allowed in ALLOWED.items():
        for path in sorted((ROOT / package).rglob("*.py")):
            for name in _imports(path):
                top = name.split(".")[0]
                if top not in allowed and top not in stdlib:
                    bad.append((str(path.relative_to(ROOT)), name))
    assert bad == []


#: the layers of exudyn_bearing (docs/ARCHITECTURE.md): each may import the ones before it
LAYERS = ("top", "results", "jacobian", "solvers", "model", "simulation", "studies")
#: modules that only gather the others (the package's public names, ``python -m``)
FACADES = {"exudyn_bearing", "exudyn_bearing.__main__"}


def _layer(module):
    parts = module.split(".")
    return parts[1] if len(parts) > 2 or (len(parts) == 2 and parts[1] in LAYERS) else "top"


def test_subpackages_import_only_earlier_layers():
    """top-level parameter modules <- results <- jacobian <- solvers <- model <- simulation <-
    studies: a subpackage never imports a later one, so the layout reads in one direction."""
    bad = []
    for module, targets in _graph().items():
        if not module.startswith("exudyn_bearing") or module in FACADES:
            continue
        for target in targets:
            if target.startswith("exudyn_bearing") and target not in FACADES:
                if LAYERS.index(_layer(target)) > LAYERS.index(_layer(module)):
                    bad.append((module, target))
    assert bad == []


def _cached_njit_functions(path):
    """Names of the functions of ``path`` compiled with ``@njit(cache=True)``."""
    names = set()
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.FunctionDef):
            for deco in node.decorator_list:
                if (isinstance(deco, ast.Call) and getattr(deco.func, "id", None) == "njit"
                        and any(k.arg == "cache" for k in deco.keywords)):
                    names.add(node.name)
    return names


def _covered_by_package_drop(path):
    """A package __init__ (contact/, contact/kernels/) that drops the caches of every module beside it."""
    init = path.parent / "__init__.py"
    return path.name != "__init__.py" and init.exists() and "drop_stale(" in init.read_text(encoding="utf-8")


def test_cached_kernels_that_call_another_files_kernels_drop_stale_caches():
    """numba's on-disk cache is keyed on a function's own file: a cached function that calls
    a cached function of another file keeps the old callee after that file changed (a changed
    surface.path_drop left the ball pits on the old law through ball_surface.py's cache).
    Every such module must call contact.kernel_cache.drop_stale."""
    offenders = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            if not _cached_njit_functions(path):
                continue
            mod = _module(path)
            base = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if not isinstance(node, ast.ImportFrom) or not node.module:
                    continue
                target = (".".join(base.split(".")[: len(base.split(".")) - (node.level - 1)] + [node.module])
                          if node.level else node.module)
                source = (ROOT / Path(*target.split("."))).with_suffix(".py")
                if not source.exists() or source == path:
                    continue
                called = {a.name for a in node.names} & _cached_njit_functions(source)
                if called and "drop_stale(" not in path.read_text(encoding="utf-8") \
                        and not _covered_by_package_drop(path):
                    offenders.append(f"{path.relative_to(ROOT)} calls {sorted(called)} of {source.relative_to(ROOT)}")
    assert not offenders, offenders


#: the constants of the laws written once as scalar numba functions (MODEL.md §3, §5): the
#: Brewe–Hamrock fits and the Hamrock–Dowson central film
ONCE = {"1.0339": "Brewe–Hamrock k", "1.5277": "Brewe–Hamrock F", "0.5968": "Brewe–Hamrock E",
        "2.69": "Hamrock–Dowson h_c", "0.067": "Hamrock–Dowson h_c's load exponent"}


def test_each_contact_law_is_written_once():
    """Each constant of those laws appears as a number in the code of one module only (the
    compiled kernels call the scalar law the numpy path applies to arrays); docstrings and
    comments do not count."""
    import io
    import tokenize

    where = {number: [] for number in ONCE}
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            tokens = tokenize.generate_tokens(io.StringIO(path.read_text(encoding="utf-8")).readline)
            numbers = {t.string for t in tokens if t.type == tokenize.NUMBER}
            for number in ONCE:
                if number in numbers:
                    where[number].append(str(path.relative_to(ROOT)))
    assert all(len(files) == 1 for files in where.values()), {ONCE[n]: f for n, f in where.items()}
