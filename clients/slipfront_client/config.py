"""Where the server is: the one place that decides the URL.

In order: the `--server` flag (or the `server` argument of `connect()`), the environment
variable SLIPFRONT_SERVER, `server = "..."` in the config file
(`$SLIPFRONT_CONFIG`, else `$XDG_CONFIG_HOME/slipfront/client.toml`, else
`~/.config/slipfront/client.toml`), and last http://127.0.0.1:8080. The token follows the
same order (`--token`, SLIPFRONT_TOKEN, `token = "..."`).
"""

import os
import re

from .errors import UsageError

try:
    import tomllib
except ModuleNotFoundError:  # Python < 3.11: the config file's `key = "string"` lines only
    tomllib = None

DEFAULT_SERVER = "http://127.0.0.1:8080"


def config_path():
    if os.environ.get("SLIPFRONT_CONFIG"):
        return os.environ["SLIPFRONT_CONFIG"]
    base = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"), ".config")
    return os.path.join(base, "slipfront", "client.toml")


def read_config(path=None):
    """The config file as a dict ({} if there is none); a broken file is a UsageError."""
    path = path or config_path()
    try:
        with open(path, "rb") as f:
            doc = tomllib.load(f) if tomllib else parse_string_lines(f.read().decode())
    except FileNotFoundError:
        return {}
    except (OSError, ValueError) as e:  # tomllib.TOMLDecodeError is a ValueError
        raise UsageError(f"config file {path}: {e}") from e
    for key in ("server", "token"):
        if key in doc and not isinstance(doc[key], str):
            raise UsageError(f"config file {path}: {key} must be a string")
    return doc


STRING_LINE = re.compile(r'([A-Za-z0-9_-]+)\s*=\s*"((?:[^"\\]|\\["\\])*)"\s*(#.*)?')


def parse_string_lines(text):
    """The config file without tomllib (Python < 3.11): blank lines, # comments and
    `key = "string"` lines (\\" and \\\\ escapes); anything else is a ValueError that names
    the line, as a TOML error would."""
    doc = {}
    for number, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        match = STRING_LINE.fullmatch(line)
        if not match:
            raise ValueError(f"line {number}: expected key = \"string\" (Python < 3.11 reads "
                             f"only those; Python 3.11+ reads any TOML)")
        doc[match.group(1)] = re.sub(r'\\(["\\])', r"\1", match.group(2))
    return doc


def resolve(flag_value, env_name, config_key, default=None):
    """(value, where it came from) for one setting."""
    if flag_value:
        return flag_value, f"--{config_key}"
    if os.environ.get(env_name):
        return os.environ[env_name], env_name
    doc = read_config()
    if doc.get(config_key):
        return doc[config_key], config_path()
    return default, "the default"


def server_url(flag_value=None):
    return resolve(flag_value, "SLIPFRONT_SERVER", "server", DEFAULT_SERVER)


def token(flag_value=None):
    return resolve(flag_value, "SLIPFRONT_TOKEN", "token", None)[0]
