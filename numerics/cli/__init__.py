"""The ``ringchain`` command: parse, call one public function, print (:mod:`.commands`; the subcommands
``fit``, ``ensemble`` and ``sheet`` in modules of their names, the shared option checks in :mod:`._options`)."""

from .commands import main

__all__ = ["main"]
