"""``python -m ringchain.numerics.cli``: the ``ringchain`` command."""

import sys

from .commands import main

sys.exit(main())
