# SPDX-License-Identifier: LGPL-2.1-or-later
"""Unit tests of the rsfcycle package (pytest): /usr/bin/python3 -m pytest python/tests."""
