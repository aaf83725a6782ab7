import sys

from .studies.cli import main
from .studies.grid import skip_final_collection

code = main()
skip_final_collection()
sys.exit(code)
