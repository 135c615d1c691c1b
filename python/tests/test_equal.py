# SPDX-License-Identifier: LGPL-2.1-or-later
"""rsfcycle.equal on hand-made catalogues: a run is unchanged when it has
the same events with every start within the bound (relative); the
cheapest unchanged run is chosen (usually the loosest; the tightest is
included), never one that changed."""

import math

from rsfcycle import catalog, equal


def events(*starts):
    return [catalog.Event(s, s + 10.0, 1.0) for s in starts]


def test_unchanged_within_the_bound():
    reference = events(1000.0, 2000.0)
    assert math.isclose(equal.unchanged(events(1000.05, 2000.0), reference), 5e-5)
    assert equal.unchanged(events(1000.2, 2000.0), reference) is None  # 2e-4
    assert equal.unchanged(events(1000.0), reference) is None  # one event lost
    assert equal.unchanged([], []) is None


def test_a_start_at_zero_is_relative_to_the_last_start():
    reference = events(0.0, 1000.0)
    assert math.isclose(equal.unchanged(events(0.05, 1000.0), reference), 5e-5)
    assert equal.unchanged(events(0.5, 1000.0), reference) is None


def test_unchanged_reads_dicts_too():
    assert equal.unchanged([dict(start=100.0)], [dict(start=100.0)]) == 0.0


def test_unchanged_values():
    assert math.isclose(equal.unchanged_values([1.0005, 2.0], [1.0, 2.0]), 5e-4)
    assert equal.unchanged_values([1.002, 2.0], [1.0, 2.0]) is None
    assert equal.unchanged_values([1.0], [1.0, 2.0]) is None


def test_the_loosest_unchanged_run_when_it_is_cheapest():
    reference = events(1000.0, 2000.0)
    runs = [("b", "3e-5", events(1000.01, 2000.0), 50.0),
            ("c", "1e-4", events(1001.0, 2000.0), 30.0),  # changed
            ("a", "1e-5", reference, 80.0)]  # any order
    chosen, states = equal.cheapest_unchanged(runs)
    assert chosen[0] == "b"
    assert [(run[0], text.split()[0]) for run, text in states] == [
        ("a", "reference"), ("b", "unchanged"), ("c", "changed")]
    assert equal.ratio(chosen, ("peer", "1e-6", None, 100.0)) == 0.5


def test_a_dearer_looser_run_is_not_taken():
    runs = [("a", "1e-5", events(100.0), 10.0), ("b", "3e-5", events(100.0), 12.0)]
    assert equal.cheapest_unchanged(runs)[0][0] == "a"


def test_the_reference_when_every_looser_run_changed():
    runs = [("a", "1e-6", events(5.0), 10.0), ("b", "1e-5", events(6.0), 5.0)]
    assert equal.cheapest_unchanged(runs)[0][0] == "a"


def test_tolerances():
    assert equal.tolerances("1e-5") == ["1e-5", "3e-5", "1e-4"]
    assert equal.tolerances("1e-6") == ["1e-6", "3e-6", "1e-5"]
