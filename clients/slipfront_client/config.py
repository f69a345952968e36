"""Where the server is: the one place that decides the URL.

In order: the `--server` flag (or the `server` argument of `connect()`), the environment
variable SLIPFRONT_SERVER, `server = "..."` in the config file
(`$SLIPFRONT_CONFIG`, else `$XDG_CONFIG_HOME/slipfront/client.toml`, else
`~/.config/slipfront/client.toml`), and last http://127.0.0.1:8080. The token follows the
same order (`--token`, SLIPFRONT_TOKEN, `token = "..."`).
"""

import os
import tomllib

from .errors import UsageError

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
            doc = tomllib.load(f)
    except FileNotFoundError:
        return {}
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise UsageError(f"config file {path}: {e}") from e
    for key in ("server", "token"):
        if key in doc and not isinstance(doc[key], str):
            raise UsageError(f"config file {path}: {key} must be a string")
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
