"""The report and plots as a reader meets them: one speed printed once, not as
"1150-1150 rpm"; efficiency in % in every table; Fig. 10's legend gives the table's mu_mean;
the sweep plot's legend carries units; µm, not "um". Built from small hand-made tables, so no
study needs to run."""

import numpy as np
import pandas as pd
import pytest

from hypoid.study import findings, plots, report, results

TRACED = {"gear_set": 1, "lubricant": 1, "lubricant_file": "", "T_s": 100.0, "status": "ok",
          "speed_rpm": 1200.0, "eta_rms": 0.98765, "DTE_pp_um": 40.0,
          "DTE_min_minus_b_um": -3.0, "contact_loss_fraction": 0.25, "W_t_mean_N": 4000.0,
          "W_t_mean_contact_N": 5000.0, "W_t_peak_N": 9000.0, "mu_mean": 0.0163,
          "h_c_mean_um": 0.2, "lambda_mean": 0.9, "point_key": "k1200", "trace": "traces/k1200"}


@pytest.fixture
def captured(monkeypatch):
    """The figures the plot functions would save, instead of files."""
    figs = {}

    def save(fig, out, name):
        figs[name] = fig
        return name

    monkeypatch.setattr(plots, "_save", save)
    return figs


def legend_texts(fig):
    return [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().texts]


def test_one_speed_is_printed_once():
    assert findings.speed_range([1150.0, 1150.0]) == "1150 rpm"
    assert findings.speed_range([1150.0, 1175.0, 1200.0]) == "1150-1200 rpm"


def test_traced_points_table_gives_efficiency_and_contact_loss_in_percent():
    pts = pd.DataFrame([TRACED])
    text = "\n".join(report._engagement_section(pts, {}))
    assert "eta_rms [%]" in text and "98.765" in text and "0.98765" not in text
    assert "contact lost [%]" in text and "| 25 |" in text
    assert "[µm]" in text and "[um]" not in text


def test_fig10_legend_gives_the_tables_mu_mean(tmp_path, captured):
    """The legend said 'mean mu in contact 0.0100' (samples of pair 1 only) where the table said
    0.0163 (load-weighted over all pairs): now it prints the table's value under its name."""
    theta = np.linspace(0, 4 * 6 * np.pi, 800)
    w = 1000.0 * (1 + np.sin(theta))
    results.write_trace(tmp_path / "traces", "k1200", TRACED,
                        {"theta": theta, "pair[1].W": w, "pair[1].mu": np.full_like(w, 0.0100)})
    plots.fig10_mesh_cycle(pd.DataFrame([TRACED]), tmp_path / "figures")
    texts = legend_texts(captured["fig10_mesh_cycle"])
    assert any("mu_mean 0.0163" in t for t in texts), texts
    assert not any("0.0100" in t for t in texts), texts


def test_sweep_plot_legend_has_units(captured):
    rows = [dict(TRACED, T_s=t, T_bath=k, speed_rpm=n, status="ok")
            for t in (50.0, 100.0) for k in (313.15, 353.15) for n in (1000.0, 2000.0)]
    plots.quick_look(pd.DataFrame(rows), "unused")
    texts = legend_texts(captured["sweep"])
    assert "T_bath = 40 °C, T_s = 50 N·m" in texts, texts
    labels = [a.get_ylabel() for a in captured["sweep"].axes]
    assert "DTE peak-to-peak [µm]" in labels


def test_fig9_legend_hides_no_resonance_label(captured):
    """The mode-3 label sat behind the legend in the upper right of the first panel: the legend
    is now the figure's, below the panels, outside every axes."""
    cont = pd.DataFrame([dict(TRACED, branch=b, speed_rpm=n, DTE_max_um=90.0, DTE_min_um=75.0,
                              b_um=70.0, contact_loss_fraction=0.0, T_s=t)
                         for t in (50.0, 100.0) for b in ("up", "down")
                         for n in (1000.0, 1500.0, 2000.0)])
    pts = pd.DataFrame([dict(TRACED, n_f2_rpm=1203.0, n_f3_rpm=2000.0)])
    plots.fig9_jump(cont, pts, "unused")
    fig = captured["fig9_dte_jump"]
    assert all(ax.get_legend() is None for ax in fig.axes)
    assert len(fig.legends) == 1
    top = min(ax.get_position().y0 for ax in fig.axes)
    fig.canvas.draw()
    box = fig.legends[0].get_window_extent().transformed(fig.transFigure.inverted())
    assert box.y1 <= top


def test_the_report_says_which_settings_made_the_tables_and_gives_the_defaults_figure():
    """Before, the report quoted the paper-choice efficiencies (99.31 % at 2000 rpm, 100 N·m,
    40 °C) without saying so, where the shipped FMU gives another figure."""
    from hypoid.study import tables as tb

    common = {"gear_set": 1, "lubricant": 1, "lubricant_file": "", "T_s": 100.0,
              "speed_rpm": 2000.0, "status": "ok", **{k: v for k, v in tb.REFERENCE.items()}}
    paper = {**common, "eta_rms": 0.9931, "P_loss_mean_W": 145.0}
    own = {**common, **{n: d for n, _, d in report.differing_defaults()},
           "eta_rms": 0.9872, "P_loss_mean_W": 268.3}
    pts = tb.prepare(pd.DataFrame([paper, own]))
    text = "\n".join(report.settings_section(pts))
    assert "tooth_data (loaded by default, paper here)" in text
    assert "roelands_z" in text and "T_bath = 40 °C" in text
    assert "99.310" in text and "98.720" in text  # both figures, side by side
    assert "268.3" in text and "145.0" in text
    assert {n for n, _, _ in report.differing_defaults()} >= {"tooth_data", "roelands_z"}
    # a table without those columns (a loss map's, a sweep's) gets the settings, no comparison
    bare = "\n".join(report.settings_section(pd.DataFrame([{"gear_set": 1, "T_s": 100.0}])))
    assert "Settings behind the tables" in bare and "FMU defaults [%]" not in bare
