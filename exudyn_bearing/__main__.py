import sys

from .studies.cli import run

sys.exit(run())
