# SPDX-License-Identifier: LGPL-2.1-or-later
"""What each SEAS benchmark's description asks of the files a code uploads:
one table per benchmark, each rule with the section of the description it
comes from. python3 -m rsfcycle.seas check reads a run folder against it;
doc/seas.md lists the same rules for users.

The descriptions (the SCEC SEAS benchmark problems):

- D1: "SEAS Benchmark Problem BP1-QD", Erickson & Jiang (2018).
- D3: "SEAS Benchmark Problems BP3-QD and BP3-FD", Erickson, Jiang &
  Dunham (2021).
- D5: "SEAS Benchmark Problems BP5-QD and BP5-FD", Jiang & Erickson (2020,
  updated 2023).
- D6: "SEAS Benchmark Problems BP6-QD-A/S/C", Lambert & Dunham (2021).
- D7: "SEAS Benchmark Problems BP7-QD/FD-A/S", Lambert, Jiang & Erickson
  (2021).
- D8: "SEAS Benchmark Problems BP8-QD-GS/PW" (Table 1 and the output
  list), as EQquasi's BP8 submission check (checkBP8Submission) reads it.

For BP1-FD, BP2-QD and BP4-QD no description could be read: their rules
follow BP1's or BP5's, and the peers' files (QDYN's BP2 stations, HBI's BP4
writer), and say so.
"""

from dataclasses import dataclass, field
from typing import List, Optional, Tuple

# The header keys of the time series: BP1 and BP2 (D1 section 4, "File
# Header"), and BP3 and later (D3 section 4.1: problem, code, version,
# modeler, date, element size, location; the time-step lines optional).
SERIES_KEYS_BP1 = ["problem", "author", "date", "code", "code_version",
                   "element_size", "location"]
SERIES_KEYS = ["problem", "code", "version", "modeler", "date",
               "element_size", "location"]
# the profiles, catalog and rupture files (D1 section 5, D5 sections
# 4.4 - 4.6): problem, author (D3: modeler), date, code, code_version,
# element size
PROFILE_KEYS = ["problem", "author", "date", "code", "code_version",
                "element_size"]
PROFILE_KEYS_BP3 = ["problem", "modeler", "date", "code", "code_version",
                    "element_size"]
# what rsfcycle fills in when the run ends (D1: "Minimum time step",
# "Maximum time step", "Number of time steps in file")
STEP_KEYS = ["minimum_time_step", "maximum_time_step", "num_time_steps"]


@dataclass
class FileRule:
    """The files of one kind: their names, their header keys, their field
    lines (each a list of names), and for profiles the positions of row 1
    (first, last, count)."""

    names: List[str]
    keys: List[str]
    fields: List[List[str]]
    source: str
    kind: str = "series"  # series, profile or table
    positions: Optional[Tuple[float, float, int]] = None
    optional: bool = False


@dataclass
class Benchmark:
    """A benchmark: its name, the problem line of its headers, the
    description its rules come from, and its files."""

    name: str
    problem: str
    description: str
    files: List[FileRule] = field(default_factory=list)
    notes: List[str] = field(default_factory=list)
    peers: List[str] = field(default_factory=list)


def _stations(prefix, labels):
    return [prefix + label for label in labels]


BP1_DEPTHS = ["000", "025", "050", "075", "100", "125", "150", "175", "200",
              "250", "300", "350"]
BP2_DEPTHS = ["000", "024", "048", "072", "096", "120", "144", "168", "192",
              "240", "288", "360"]
BP1_STATION_FIELDS = [["t", "slip", "slip_rate", "shear_stress", "state"]]


def _bp1(name, problem, depths, description, notes):
    return Benchmark(
        name, problem, description,
        [FileRule(_stations("fltst_dp", depths), SERIES_KEYS_BP1 + STEP_KEYS,
                  BP1_STATION_FIELDS,
                  "D1 section 4: 12 stations fltst_dpXXX (depth in 100 m), "
                  "no extension; the field line t slip slip_rate "
                  "shear_stress state"),
         FileRule(["devol.dat"], PROFILE_KEYS,
                  [["z"], ["t", "max_slip_rate", "slip"]],
                  "D1 section 5: the slip evolution devol.dat, two field "
                  "lines (z, then t max_slip_rate slip), row 1 the depths "
                  "every ~500 m down to 40 km",
                  kind="profile", positions=(0.0, 40e3, 81))],
        notes)


BP3_STATIONS = _stations("fltst_dp", BP1_DEPTHS)
BP3_SURFACE = _stations("srfst_fn", ["-32", "-16", "-08", "-00", "+00", "+08",
                                     "+16", "+32"])


def _bp3(name):
    return Benchmark(
        name, "SEAS Benchmark " + name,
        "D3 (BP3-QD and BP3-FD), section 4",
        [FileRule(BP3_STATIONS, SERIES_KEYS + STEP_KEYS,
                  [["t", "slip", "slip_rate", "shear_stress", "normal_stress",
                    "state"]],
                  "D3 section 4.1: 12 stations fltst_dpXXX (down-dip "
                  "distance in 100 m), the normal stress column"),
         FileRule(BP3_SURFACE, SERIES_KEYS + STEP_KEYS,
                  [["t", "disp_1", "disp_2", "vel_1", "vel_2"]],
                  "D3 section 4.2: 8 surface stations srfst_fn+XX (the "
                  "text says 7 and lists 8)"),
         FileRule(["slip.dat", "shear_stress.dat", "normal_stress.dat"],
                  PROFILE_KEYS_BP3,
                  [["x_d"], ["t", "max_slip_rate", "FIELD"]],
                  "D3 section 4.3: slip, shear and normal stress profiles, "
                  "two field lines (x_d, then t max_slip_rate FIELD), row 1 "
                  "every ~500 m from 0 to 40 km down dip",
                  kind="profile", positions=(0.0, 40e3, 81))],
        ["Label the upload thrust or normal (D3 section 4): "
         "Output/SEAS/Description."])


PLANE_FIELDS = [["t", "slip_2", "slip_3", "slip_rate_2", "slip_rate_3",
                 "shear_stress_2", "shear_stress_3", "state"]]
BLOCK_FIELDS = [["t", "disp_1", "disp_2", "disp_3", "vel_1", "vel_2",
                 "vel_3"]]
CATALOG_FIELDS = [["event_no", "t_start", "t_end", "rup_area",
                   "avg_stress_start", "avg_stress_end", "avg_slip"]]


def _profiles_3d(prefix, strike, depth, source, optional=False, extra=()):
    rules = []
    for line, name, positions in (("strike", "x2", strike),
                                  ("depth", "x3", depth)):
        for quantity in ("slip_2", "slip_3", prefix + "_2", prefix + "_3",
                         *extra):
            rules.append(FileRule(
                [quantity + "_" + line + ".dat"], PROFILE_KEYS,
                [[name], ["t"], ["max_slip_rate"], [quantity]], source,
                kind="profile", positions=positions, optional=optional))
    return rules


BP4_STATIONS = _stations("fltst_strk", [
    "-360dp+000", "-225dp-750", "-165dp-120", "-165dp+000", "-165dp+120",
    "+000dp-210", "+000dp-120", "+000dp+000", "+000dp+120", "+000dp+210",
    "+165dp-120", "+165dp+000", "+165dp+120", "+360dp+000"])
BP5_STATIONS = _stations("fltst_strk", [
    "-36dp+00", "-16dp+00", "+00dp+00", "+16dp+00", "+36dp+00", "-24dp+10",
    "-16dp+10", "+00dp+10", "+16dp+10", "+00dp+22"])
BP5_BLOCKS = _stations("blkst_strk", [
    "-16fn+08dp+00", "+00fn+08dp+00", "+16fn+08dp+00", "+00fn+16dp+00",
    "+00fn+32dp+00", "+00fn+48dp+00", "+00fn+08dp+10", "+00fn+16dp+10",
    "+00fn+32dp+10"])
BP6_STATIONS = _stations("fltst_strk", ["-15", "+00", "+05", "+10", "+15",
                                        "+25", "+35", "+50", "+75"])
BP7_STATIONS = _stations("fltst_strk", [
    "+000dp+000", "-100dp+000", "+000dp+100", "+100dp+000", "+000dp-100",
    "-100dp-100", "-100dp+100", "+100dp-100", "+100dp+100", "-300dp+000",
    "+000dp+300", "+300dp+000", "+000dp-300"])
BP7_BLOCKS = _stations("blkst_strk", [
    "+000fn+200dp+000", "+000fn+400dp+000", "-300fn+400dp+000",
    "+000fn+400dp+300", "+300fn+400dp+000", "+000fn+400dp-300"])


BP8_STATIONS = [f"fltst_strk{x2:+04d}dp{x3:+04d}.dat"
                for x2 in (-200, 0, 200) for x3 in (-200, 0, 200)]


def _bp8(name):
    return Benchmark(
        name, "SEAS Benchmark " + name,
        "D8 (BP8-QD-GS/PW), its output list",
        [FileRule(BP8_STATIONS, SERIES_KEYS + STEP_KEYS,
                  [PLANE_FIELDS[0][:-1] + ["pore_pressure", "darcy_vel_2",
                                           "darcy_vel_3", "state"]],
                  "D8: 9 stations fltst_strk+XXXdp+YYY.dat (m) at x2, x3 "
                  "in {-200, 0, 200} m, 11 fields"),
         FileRule(["global.dat"], SERIES_KEYS + STEP_KEYS,
                  [["t", "max_slip_rate", "moment_rate"]],
                  "D8: the moment rate over the frictional domain")]
        + _profiles_3d("shear_stress", (-400.0, 400.0, 81),
                       (-400.0, 400.0, 81),
                       "D8: from -400 to 400 m at exactly 10 m",
                       extra=("pore_pressure",)),
        ["Every file ends in .dat (the platform ignores .txt); no "
         "catalog, rupture times or off-fault stations."])


def _bp6(name, problem):
    return Benchmark(
        name, problem, "D6 (BP6-QD-A/S/C), section 4",
        [FileRule(BP6_STATIONS, SERIES_KEYS + STEP_KEYS,
                  [["t", "slip", "slip_rate", "shear_stress",
                    "pore_pressure", "darcy_vel", "state"]],
                  "D6 section 4.1: 9 stations fltst_strk+XX (x in 100 m, "
                  "signed)"),
         FileRule(["global.dat"], SERIES_KEYS + STEP_KEYS,
                  [["t", "max_slip_rate", "moment_rate"]],
                  "D6 section 4.2: max slip rate and moment density rate "
                  "(N/s) over the frictional domain"),
         FileRule(["slip.dat", "shear_stress.dat", "normal_stress.dat",
                   "darcy_vel.dat"], PROFILE_KEYS,
                  [["z"], ["t"], ["max_slip_rate"], ["FIELD"]],
                  "D6 section 4.3: four profiles, four field lines, row 1 "
                  "every ~100 m from -10 to 10 km",
                  kind="profile", positions=(-10e3, 10e3, 201))])


def _bp5(name):
    """BP5-QD and BP5-FD: D5 asks both for the same files (section 4)."""
    return Benchmark(
        name, "SEAS Benchmark " + name, "D5 (BP5-QD and BP5-FD), section 4",
        [FileRule(BP5_STATIONS, SERIES_KEYS + STEP_KEYS, PLANE_FIELDS,
                  "D5 section 4.1: 10 stations fltst_strk+XXdp+YY (km)"),
         FileRule(BP5_BLOCKS, SERIES_KEYS + STEP_KEYS, BLOCK_FIELDS,
                  "D5 section 4.2: 9 off-fault stations blkst_*"),
         FileRule(["global.dat"], SERIES_KEYS + STEP_KEYS,
                  [["t", "max_slip_rate", "moment_rate"]],
                  "D5 section 4.3: over |x2| <= 34 km, x3 <= 20 km"),
         FileRule(["catalog.dat"], PROFILE_KEYS, CATALOG_FIELDS,
                  "D5 section 4.4: the earthquake catalog", kind="table"),
         FileRule(["rupture.dat"], PROFILE_KEYS, [["x2", "x3", "t"]],
                  "D5 section 4.6: the first event's rupture times, 1e9 "
                  "where a node never ruptures", kind="table")]
        + _profiles_3d("stress", (-38e3, 38e3, 77), (0.0, 40e3, 41),
                       "D5 section 4.5: slip_2, slip_3, stress_2, stress_3 "
                       "along strike at 10 km and down dip at x2 = 0, four "
                       "field lines"))


BENCHMARKS = [
    _bp1("BP1-QD", "SEAS Benchmark No.1", BP1_DEPTHS, "D1, sections 4 and 5",
         ["D1 asks for no global.dat or surface stations: the station at "
          "0 km is the surface."]),
    _bp1("BP1-FD", "SEAS Benchmark BP1-FD", BP1_DEPTHS,
         "none stored: BP1-QD's files (D1), as the codes that ran BP1-FD "
         "write them",
         ["No description of BP1-FD could be read; its files follow "
          "BP1-QD's."]),
    _bp1("BP2-QD", "SEAS Benchmark No.2", BP2_DEPTHS,
         "none stored: BP1-QD's files (D1) at BP2's stations",
         ["BP2's stations every 2.4 km (0 ... 19.2, 24, 28.8, 36 km) are "
          "those of QDYN's BP2 script and of the benchmark authors' "
          "reference files; no description could be read."]),
    _bp3("BP3-QD"),
    _bp3("BP3-FD"),
    Benchmark(
        "BP4-QD", "SEAS Benchmark BP4-QD",
        "none stored past its opening: HBI's BP4 writer, BP5's conventions",
        [FileRule(BP4_STATIONS, SERIES_KEYS + STEP_KEYS, PLANE_FIELDS,
                  "HBI's BP4 writer: 14 stations named in 100 m, the "
                  "nucleation square's centre fltst_strk-225dp-750"),
         FileRule(["global.dat"], SERIES_KEYS + STEP_KEYS,
                  [["t", "max_slip_rate", "moment_rate"]],
                  "HBI's BP4 writer"),
         FileRule(["rupture.dat"], PROFILE_KEYS, [["x2", "x3", "t"]],
                  "HBI's BP4 writer", kind="table")]
        + _profiles_3d("stress", (-48e3, 48e3, 97), (-36e3, 36e3, 73),
                       "BP5's profiles (D5 section 4.5), optional for BP4",
                       optional=True),
        ["HBI names the station at (-22.5, -7.5) km fltst_strk-225dp-750, "
         "which breaks the 100 m naming of the others (it would be "
         "dp-075); rsfcycle writes HBI's name."]),
    _bp5("BP5-QD"),
    _bp5("BP5-FD"),
    _bp6("BP6-QD-A", "SEAS Benchmark BP6-A"),
    _bp6("BP6-QD-S", "SEAS Benchmark BP6-S"),
    Benchmark(
        "BP7-QD", "SEAS Benchmark BP7-QD-A",
        "D7 (BP7-QD/FD-A/S), section 4",
        [FileRule(BP7_STATIONS, SERIES_KEYS + STEP_KEYS, PLANE_FIELDS,
                  "D7 section 4.1: 13 stations named in m"),
         FileRule(BP7_BLOCKS, SERIES_KEYS + STEP_KEYS, BLOCK_FIELDS,
                  "D7 section 4.2: 6 off-fault stations"),
         FileRule(["global.dat"], SERIES_KEYS + STEP_KEYS,
                  [["t", "max_slip_rate", "moment_rate", "moment_rate_vw"]],
                  "D7 section 4.3: within 1.5 R_VW, and over the VW disc"),
         FileRule(["catalog.dat"], PROFILE_KEYS, CATALOG_FIELDS,
                  "D7 section 4.4", kind="table"),
         FileRule(["rupture.dat"], PROFILE_KEYS, [["x2", "x3", "t"]],
                  "D7 section 4.6", kind="table")]
        + _profiles_3d("stress", (-400.0, 400.0, 81), (-400.0, 400.0, 81),
                       "D7 section 4.5: from -400 to 400 m every 10 m")),
    _bp8("BP8-QD-GS"),
    _bp8("BP8-QD-PW"),
]


def by_problem(problem):
    """The benchmark whose problem line is `problem` (None: unknown)."""
    for benchmark in BENCHMARKS:
        if benchmark.problem == problem:
            return benchmark
    return None


# Where the peers' files differ from the descriptions (rsfcycle follows the
# descriptions).
PEERS = {
    "BP1-QD": ["QDYN's BP1 writer labels devol.dat's second column the "
               "maximum slip rate in m/s, where D1 asks for log10 m/s; "
               "Thrase names the file slip.dat, without a header."],
    "BP2-QD": ["QDYN's BP2 script writes `problem=SEAS Benchmark No.1` and "
               "names the profile devol_dz=....dat."],
    "BP3-QD": ["HBI writes the profiles' first field line `xd` (D3: `x_d`) "
               "and `Column #3-83` (D3: `Columns #3-83`)."],
    "BP3-FD": ["As BP3-QD; the off-fault header example of D3 names only "
               "BP3-QD."],
    "BP4-QD": ["interact (IA) places the station fltst_strk-225dp-750 at "
               "(-22.5, -7.5) km, the nucleation square's centre, as "
               "rsfcycle does."],
    "BP5-QD": ["EQquasi writes fltst_strk-036dp000.txt and renames its "
               "files afterwards; its older header labels the off-fault "
               "velocities log10 m/s (D5: not log10); tandem nucleates "
               "with V_i = 0.01 m/s (D5: 0.03 m/s)."],
    "BP5-FD": ["As BP5-QD."],
    "BP6-QD-A": ["HBI's global.dat has 5 columns under a 3-name field "
                 "line, and its profiles' 'Computational domain size' line "
                 "lacks its '#'."],
    "BP6-QD-S": ["As BP6-QD-A."],
    "BP7-QD": ["A GEOS BP7 writer misspells the fifth field (`Slip rate "
               "3`); Thrase separates the fields by tabs; D7 gives D_RS = "
               "0.50/0.53 mm without saying which goes with which law "
               "(rsfcycle: 0.53 mm, as HBI)."],
    "BP8-QD-GS": ["EQquasi also writes two off-fault points, (0, 200, 0) "
                  "and (0, 400, 0) m, which the output list does not "
                  "name; rsfcycle writes none."],
    "BP8-QD-PW": ["As BP8-QD-GS."],
}
for _benchmark in BENCHMARKS:
    _benchmark.peers = PEERS.get(_benchmark.name, [])


def markdown():
    """doc/seas.md's section on the files: per benchmark its files, each
    with the description's rule, the notes and the peers' differences."""
    lines = []
    for b in BENCHMARKS:
        lines.append(f"### {b.name}")
        lines.append("")
        lines.append(f"Problem line `{b.problem}`; rules from: "
                     f"{b.description}.")
        lines.append("")
        lines.append("| files | field lines | rule |")
        lines.append("|---|---|---|")
        for rule in b.files:
            names = rule.names
            shown = ", ".join(f"`{n}`" for n in names[:3])
            if len(names) > 3:
                shown += f" … ({len(names)} files)"
            if rule.optional:
                shown += " (optional)"
            fields = " / ".join(" ".join(line) for line in rule.fields)
            lines.append(f"| {shown} | `{fields}` | {rule.source} |")
        lines.append("")
        for note in b.notes:
            lines.append(f"- {note}")
        for peer in b.peers:
            lines.append(f"- Peers: {peer}")
        if b.notes or b.peers:
            lines.append("")
    return "\n".join(lines)
