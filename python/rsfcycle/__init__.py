# SPDX-License-Identifier: LGPL-2.1-or-later
"""Python tools for rsfcycle's run folders, benchmarks and documents.

Importable with ``PYTHONPATH=python`` from the repository's root, or after
``pip install -e python``. Only numpy, pandas and matplotlib are needed.
"""

__version__ = "0.1.0"
