"""``python -m reflectance``: the same as the ``reflectance`` command."""

import sys

from reflectance.cli import main

sys.exit(main())
