"""`python3 -m slipfront_client ...` (with clients/ on sys.path)."""

import sys

from .cli import main

sys.exit(main())
