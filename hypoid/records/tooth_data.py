"""The records of the loaded tooth data and the friction level (docs/physics.md §10.8,
docs/friction-evidence.md): what the stiffness level does at 2000 rpm (km-effect, by
tools/tooth_figures.py), the mesh force laws against the reference model (mesh-law, by
tools/mesh_law_reference.py), and μ, P_loss and DTE before and after a change of settings
(friction-tooth-data, friction-defaults, by tools/friction_figures.py)."""

from hypoid.records.pages import head, load, minus, table

OILS = {1: "OS265962", 2: "OS265963"}


# ------------------------------------------------------------------ km-effect

def km_effect(record, folder, _old=None):
    rows = load(folder, record.data[0])["rows"]
    lines = []
    for n, t, scale, *points in rows:
        base = points[0]
        lines.append([str(n), f"{t:g}", f"{scale:.2f}",
                      " / ".join(f"{100 * p[0]:.3f}" for p in points),
                      " / ".join(f"{p[1]:.1f}" for p in points),
                      " / ".join(minus(f"{100 * (p[1] / base[1] - 1):+.1f} %") for p in points[1:]),
                      " / ".join(f"{1e6 * p[2]:.1f}" for p in points)])
    intro = ("Gear sets 1-3 at 2000 rpm, 50 and 300 N·m (`load_mode = speed`, 0.3 s, the FMU's "
             "friction defaults), with three tooth data: the built-in one-series files (the "
             "calibrated `k_m0` of docs/physics.md §8.4); the same with `k_m_scale` set to the "
             "loaded tangent level `k̄_t(T)/k_m0` (the stiffness level alone); and the layered "
             "files of `hypoid tca surrogate --loaded` (both flanks, 25–400 N·m, the contact law), "
             "which also bring the loaded ripple, load shares, contact radius and unloaded "
             "transmission error. The change of `P_loss_cycle` is relative to the one-series "
             "data. The figure is [km_effect.png](../figures/km_effect.png).")
    return (head(record) + "\n" + intro + "\n\n"
            + table(["set", "T_s [N·m]", "k_m_scale",
                     "eta_cycle [%] one-series / scaled / layered", "P_loss_cycle [W]", "change",
                     "DTE peak to peak [µm]"], lines) + "\n")


# ------------------------------------------------------------------ mesh-law

LAW_COLUMNS = (("reference", "reference (the contact's W(δ, θ))"),
               ("fmu", "FMU (power laws through the levels, instantaneous)"),
               ("secant", "filtered secant (the former law)"),
               ("tangent", "tangent per level"))
MODE2_BAND = (1000.0, 1800.0)  # [rpm] where a sweep's mode-2 peak is looked for


def _peak(speeds, runs, band):
    i = max((k for k, n in enumerate(speeds) if band[0] <= n <= band[1]),
            key=lambda k: runs[k]["pp_um"])
    return speeds[i], runs[i]


def _cell(n, r):
    apart = f", apart {100 * r['apart']:.1f} %" if r["apart"] > 0 else ""
    return f"{n:.0f} rpm, {r['pp_um']:.1f} µm{apart}"


def law_rows(speeds, runs):
    """Per law: the peaks, the DTE at 2000 rpm, where the teeth part and the largest difference
    from the reference over the sweep."""
    at, ref = speeds.index(2000.0), runs["reference"]
    dev_key = f"largest difference from the reference, {speeds[0]:.0f}–{speeds[-1]:.0f} rpm"
    rows = {"mode-2 peak": [], "mode-3 peak": [], "2000 rpm": [], "mean DTE − b at 2000 rpm": [],
            "teeth apart (speeds of the sweep)": [], dev_key: []}
    for key, _ in LAW_COLUMNS:
        r = runs[key]
        rows["mode-2 peak"].append(_cell(*_peak(speeds, r, MODE2_BAND)))
        rows["mode-3 peak"].append(_cell(*_peak(speeds, r, (MODE2_BAND[1], speeds[-1]))))
        rows["2000 rpm"].append(f"{r[at]['pp_um']:.2f} µm")
        rows["mean DTE − b at 2000 rpm"].append(f"{r[at]['mean_minus_b_um']:.2f} µm")
        apart = [n for n, s in zip(speeds, r) if s["apart"] > 0]
        rows["teeth apart (speeds of the sweep)"].append(
            ", ".join(f"{n:.0f}" for n in apart) + " rpm" if apart else "none")
        dev = max(abs(s["pp_um"] / q["pp_um"] - 1.0) for s, q in zip(r, ref))
        rows[dev_key].append("–" if key == "reference" else f"{100 * dev:.0f} %")
    return [[k, *v] for k, v in rows.items()]


def mesh_law(record, folder, _old=None):
    rec = load(folder, record.data[0])
    speeds = rec["speeds"]
    out = [head(record, f"Recorded on {rec['commit']}, {rec['recorded']}, with {rec['file']}."),
           "The 4-DoF model of docs/physics.md §8.1 (frictionless, both ends torque-driven, "
           "Table 3, the file's `R_p` and `e₀`) with four mesh force laws: the loaded contact's own "
           "`W(x − b, θ)` tabulated from `hypoid.tca.loaded` at 62 loads × 256 mesh angles (the "
           "reference, RK4 at 5 µs), the FMU itself on the same file (through fmpy, 10 µs "
           "communication steps), the files' secant blended at the filtered torque, and a tangent "
           "linearised about each level. All four run with the dampers the FMU computes, so that "
           "only the law differs. DTE peak to peak over 0.2–0.3 s, gear set 1."]
    for t, d in rec["torques"].items():
        s = d["fmu_setup"]
        out += [f"## {t} N·m", "",
                table([f"{t} N·m, DTE p-p", *(c for _, c in LAW_COLUMNS)],
                      law_rows(speeds, d["runs"])), "",
                f"At {t} N·m the FMU computed k_m0 = {s['k_m0'] / 1e8:.2f}·10⁸ N/m, the "
                f"contact's mean tangent being {d['k_t_contact'] / 1e8:.2f}·10⁸ and the file's "
                f"secant {d['k_m_secant'] / 1e8:.2f}·10⁸; f_3 = {s['f_3']:.1f} Hz; dampers "
                f"c_t1 = {s['c_t1']:.3f} N·m·s/rad, c_m = {s['c_m']:.0f} N·s/m, "
                f"c_t2 = {s['c_t2']:.2f} N·m·s/rad, used in all four.", ""]
    return "\n".join(out[:1]) + "\n" + "\n".join(out[1:]).rstrip() + "\n"


# ------------------------------------------------------------------ friction before and after

def friction(record, folder, _old=None):
    rec = load(folder, record.data[0])
    a, b = (" ".join(s.split("=", 1)[-1] for s in rec[k].split()) for k in ("before", "after"))
    a, b = a or "default", b or "default"
    mz = all("mu_mZ" in r for r in rec["rows"])
    columns = ["oil", "rpm", "N·m", f"μ {a} → {b}"] + (["μ_mZ ISO/TR 14179-2"] if mz else []) + [
        f"P_loss {a} → {b} [W]", "ΔP_loss / P_loss", f"η_rms {a} → {b}",
        f"DTE p-p {a} → {b} [µm]", "teeth apart [%]"]
    rows = []
    for r in rec["rows"]:
        x, y = r["before"], r["after"]
        dP = 100 * (y["P_loss_mean_W"] / x["P_loss_mean_W"] - 1.0)
        rows.append([OILS[r["lubricant"]], f"{r['rpm']:.0f}", f"{r['T_s']:.0f}",
                     f"{x['mu_mean']:.4f} → {y['mu_mean']:.4f}"]
                    + ([f"{r['mu_mZ']:.4f}"] if mz else [])
                    + [f"{x['P_loss_mean_W']:.1f} → {y['P_loss_mean_W']:.1f}", minus(f"{dP:+.1f} %"),
                       f"{x['eta_rms']:.4f} → {y['eta_rms']:.4f}",
                       f"{x['DTE_pp_um']:.1f} → {y['DTE_pp_um']:.1f}",
                       f"{100 * x['contact_loss_fraction']:.0f} → "
                       f"{100 * y['contact_loss_fraction']:.0f}"])

    def change(q):
        c = [100 * (r["after"][q] / r["before"][q] - 1.0) for r in rec["rows"]]
        return minus(f"{min(c):+.1f} … {max(c):+.1f} %")

    intro = (f"Full model, gear set 1, 40 °C bath, the regression scenarios' protocol (governor "
             f"at speed, 60 mesh cycles to settle and 20 recorded), with `{rec['before']}` and "
             f"with {f'`{after}`' if (after := rec['after']) else 'the defaults'}; μ "
             "load-weighted over the pairs, P_loss "
             "the mean mesh friction loss. The last row is the operating point of the worked "
             "example of docs/physics.md §12."
             + (" μ_mZ is ISO/TR 14179-2's mean coefficient of the mesh for a mineral oil "
                "(`X_L` = 1; the same for both oils, which share their viscosity data; "
                "docs/friction-evidence.md)." if mz else ""))
    summary = (f"P_loss changes by {change('P_loss_mean_W')} of itself, μ by {change('mu_mean')}, "
               f"the DTE peak to peak by {change('DTE_pp_um')}.")
    return (head(record, f"Recorded on {rec['commit']}, {rec['recorded']}.") + "\n" + intro
            + "\n\n" + table(columns, rows) + "\n\n" + summary + "\n")
