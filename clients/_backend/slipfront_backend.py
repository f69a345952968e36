"""The build backend of clients/pyproject.toml: builds the slipfront-client wheel (and sdist)
with the standard library only, so that `pip install ./clients` works offline with any
Python >= 3.9 that has pip, without setuptools or wheel (docs/python-api.md "Install").

The hooks pip calls (PEP 517, and PEP 660 for `pip install -e`): get_requires_for_build_*,
prepare_metadata_for_build_wheel/_editable, build_wheel, build_editable, build_sdist.
The metadata is the [project] table of pyproject.toml, read by `read_project` (a reader of
the few TOML forms that table uses: tomllib is Python 3.11+); the version is
`__version__` of slipfront_client/__init__.py.
"""

import ast
import base64
import hashlib
import io
import os
import re
import tarfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE = "slipfront_client"
# Fixed timestamp (1980-01-01, the zip epoch) so that a wheel's bytes depend on its files only.
ZIP_TIME = (1980, 1, 1, 0, 0, 0)


# -- pyproject.toml -------------------------------------------------------------------------

def _strip_comment(line):
    """The line without a trailing # comment (a # inside a "string" is kept)."""
    in_string = False
    for i, c in enumerate(line):
        if c == '"' and (i == 0 or line[i - 1] != "\\"):
            in_string = not in_string
        elif c == "#" and not in_string:
            return line[:i]
    return line


def _value(text, where):
    """A TOML value of the forms pyproject.toml uses: "string", [list of values],
    {key = value, ...} (inline table), true, false."""
    python = text.strip()
    if python in ("true", "false"):
        return python == "true"
    if python.startswith("{"):  # {key = "value", ...}: keys quoted, = as :
        python = re.sub(r'([{,]\s*)([A-Za-z0-9_-]+)\s*=', r'\1"\2":', python)
    try:
        return ast.literal_eval(python)
    except (ValueError, SyntaxError) as e:
        raise ValueError(f"pyproject.toml {where}: cannot read value {text.strip()!r}") from e


def read_pyproject(path):
    """{table name: {key: value}} of a pyproject.toml written with the forms of `_value`."""
    tables = {"": {}}
    table = tables[""]
    pending = ""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for number, raw in enumerate(lines, 1):
        line = _strip_comment(raw).strip()
        if not line and not pending:
            continue
        if pending:
            line = pending + " " + line
        if line.count("[") + line.count("{") > line.count("]") + line.count("}"):
            pending = line  # a value continued on the next line
            continue
        pending = ""
        header = re.fullmatch(r"\[([A-Za-z0-9_.-]+)\]", line)
        if header:
            table = tables.setdefault(header.group(1), {})
            continue
        key, sep, value = line.partition("=")
        key = key.strip().strip('"')
        if not sep or not re.fullmatch(r"[A-Za-z0-9_.-]+", key):
            raise ValueError(f"pyproject.toml line {number}: expected key = value: {raw!r}")
        table[key] = _value(value, f"line {number}")
    if pending:
        raise ValueError("pyproject.toml: a value is not closed at the end of the file")
    return tables


def version():
    with open(os.path.join(ROOT, PACKAGE, "__init__.py"), encoding="utf-8") as f:
        match = re.search(r'^__version__ = "([^"]+)"', f.read(), re.MULTILINE)
    if not match:
        raise ValueError(f"no __version__ = \"...\" in {PACKAGE}/__init__.py")
    return match.group(1)


def read_project():
    """The [project] table with its version filled in, and [project.scripts]."""
    tables = read_pyproject(os.path.join(ROOT, "pyproject.toml"))
    project = dict(tables.get("project", {}))
    project["version"] = version()
    project["optional-dependencies"] = tables.get("project.optional-dependencies", {})
    project["scripts"] = tables.get("project.scripts", {})
    return project


def metadata_text(project):
    """METADATA (core metadata 2.1) of the wheel, PKG-INFO of the sdist."""
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}",
             f"Version: {project['version']}", f"Summary: {project['description']}"]
    if "license" in project:
        lines.append(f"License: {project['license']['text']}")
    lines.append(f"Requires-Python: {project['requires-python']}")
    lines += [f"Requires-Dist: {d}" for d in project.get("dependencies", [])]
    for extra, deps in project["optional-dependencies"].items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {d}; extra == "{extra}"' for d in deps]
    readme = project.get("readme")
    if readme:
        lines.append("Description-Content-Type: text/markdown")
        with open(os.path.join(ROOT, readme), encoding="utf-8") as f:
            return "\n".join(lines) + "\n\n" + f.read()
    return "\n".join(lines) + "\n"


def dist_info_files(project):
    """{name inside .dist-info: bytes}, without RECORD."""
    scripts = "".join(f"{name} = {target}\n" for name, target in project["scripts"].items())
    return {
        "METADATA": metadata_text(project).encode(),
        "WHEEL": (b"Wheel-Version: 1.0\nGenerator: slipfront_backend\n"
                  b"Root-Is-Purelib: true\nTag: py3-none-any\n"),
        "entry_points.txt": f"[console_scripts]\n{scripts}".encode(),
        "top_level.txt": f"{PACKAGE}\n".encode(),
    }


def dist_name(project):
    return re.sub(r"[-_.]+", "_", project["name"]).lower()


# -- the wheel ------------------------------------------------------------------------------

def package_files():
    """(path inside the wheel, path on disk) of the package's .py and .json files."""
    found = []
    for folder, dirs, files in os.walk(os.path.join(ROOT, PACKAGE)):
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        for name in sorted(files):
            if name.endswith((".py", ".json")):
                disk = os.path.join(folder, name)
                found.append((os.path.relpath(disk, ROOT).replace(os.sep, "/"), disk))
    return found


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def _write_wheel(directory, members):
    """Write {name: bytes} as a wheel (RECORD added) in `directory`; return its file name."""
    project = read_project()
    base = f"{dist_name(project)}-{project['version']}"
    info = f"{base}.dist-info"
    members = dict(members)
    for name, data in dist_info_files(project).items():
        members[f"{info}/{name}"] = data
    record = [_record_line(name, data) for name, data in members.items()] + [f"{info}/RECORD,,"]
    members[f"{info}/RECORD"] = ("\n".join(record) + "\n").encode()
    filename = f"{base}-py3-none-any.whl"
    with zipfile.ZipFile(os.path.join(directory, filename), "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in members.items():
            entry = zipfile.ZipInfo(name, ZIP_TIME)
            entry.external_attr = 0o644 << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(entry, data)
    return filename


def _read(path):
    with open(path, "rb") as f:
        return f.read()


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_editable(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def _prepare_metadata(metadata_directory):
    project = read_project()
    info = f"{dist_name(project)}-{project['version']}.dist-info"
    os.makedirs(os.path.join(metadata_directory, info), exist_ok=True)
    for name, data in dist_info_files(project).items():
        with open(os.path.join(metadata_directory, info, name), "wb") as f:
            f.write(data)
    return info


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _prepare_metadata(metadata_directory)


def prepare_metadata_for_build_editable(metadata_directory, config_settings=None):
    return _prepare_metadata(metadata_directory)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    return _write_wheel(wheel_directory, {name: _read(disk) for name, disk in package_files()})


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    """A wheel holding only a .pth file that puts this clients/ folder on sys.path: edits to
    the sources take effect without reinstalling."""
    return _write_wheel(wheel_directory, {f"_{PACKAGE}_editable.pth": (ROOT + "\n").encode()})


def build_sdist(sdist_directory, config_settings=None):
    project = read_project()
    base = f"{dist_name(project)}-{project['version']}"
    filename = f"{base}.tar.gz"
    files = [("pyproject.toml", os.path.join(ROOT, "pyproject.toml")),
             ("README.md", os.path.join(ROOT, "README.md")),
             ("_backend/slipfront_backend.py", os.path.abspath(__file__))] + package_files()
    with tarfile.open(os.path.join(sdist_directory, filename), "w:gz",
                      format=tarfile.PAX_FORMAT) as tar:
        def add(name, data):
            entry = tarfile.TarInfo(f"{base}/{name}")
            entry.size, entry.mode, entry.mtime = len(data), 0o644, 315532800
            tar.addfile(entry, io.BytesIO(data))
        add("PKG-INFO", metadata_text(project).encode())
        for name, disk in files:
            add(name, _read(disk))
    return filename
