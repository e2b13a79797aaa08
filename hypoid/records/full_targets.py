"""The full-targets record: the full model at the FMU's defaults against ARKODE's explicit pair at
rtol 1e-4 and the paper's Newmark at 50 steps per mesh cycle, cost and accuracy (measured by
bench/full_targets.py into full-targets.json)."""

from hypoid.records.pages import head, load


def fmt(x, digits=2):
    return f"{x:.{digits}e}"


def cost(data):
    m, t = data["meta"], data["targets"]
    L = ["## Cost (C host, one run)", "",
         f"`{m['command']}` (FMU_DIR: the FMU unzipped): 2000 rpm held by the speed governor, "
         f"100 N.m, 40 degC, 1 ms communication steps, {m['runs']} interleaved batches of "
         f"~{m['cpu']} s CPU after 0.2 s start-up, medians; six outputs read per step.", "",
         "| candidate | real-time factor | relative to Newmark 50/cycle | us per mesh cycle | "
         "solver steps per mesh cycle | rhs evaluations per mesh cycle |",
         "|---|---|---|---|---|---|"]
    for c in data["candidates"]:
        L.append(f"| {c['label']} | {c['rtf']:.1f} | {c['ratio']:.1f} | {c['us_cycle']:.1f} | "
                 f"{c['steps']:.3g} | {c['rhs']:.3g} |")
    L.append("")
    for c in data["candidates"]:
        if not c["checked"]:
            continue
        accurate = all(r["ok"] for s in data["scenes"] for r in s["results"]
                       if r["label"] == c["label"])
        L.append(f"* {c['label']}: **{c['rtf']:.1f}x** real time (target >= {t['rtf']:.0f}x: "
                 f"{'met' if c['rtf'] >= t['rtf'] else 'not met'}), **{c['ratio']:.1f}x** "
                 f"Newmark at 50 steps per mesh cycle (target >= {t['newmark_ratio']:.0f}x: "
                 f"{'met' if c['ratio'] >= t['newmark_ratio'] and accurate else 'not met'}); "
                 f"within the required accuracy in all {len(data['scenes'])} scenes: "
                 f"{'yes' if accurate else '**no**'}.")
    L += ["", "Newmark runs the direct friction solve (the friction table is not used with "
          "Newmark: its Newton iteration with a difference Jacobian did not converge on it in an "
          "extremes case), so part of the ratio is the table's; its Newton iteration costs "
          f"{data['newmark_rhs_per_step']:.1f} right-hand sides per step."]
    return L


def accuracy(data):
    t, labels = data["targets"], [c["label"] for c in data["candidates"]]
    L = ["## Accuracy against the tight reference (CVODE BDF, rtol 1e-10)", "",
         f"{len(data['scenes'])} scenes of bench/wp_driver.py (0.5 s each with the start-up; "
         "errors over the scene's window): |d eta_cycle| in %-points and |d DTE p-p| in µm. "
         f"Required for the defaults and arkode_erk: <= {t['eta_pt']:g} %-point and "
         f"<= {t['dte_um']:g} µm.", "",
         "| scene | reference eta_cycle | reference DTE p-p [µm] | "
         + " | ".join(f"{k}: d eta [%-pt] / d DTE p-p [µm]" for k in labels) + " |",
         "|---|---|---|" + "---|" * len(labels)]
    checked = {c["label"]: c["checked"] for c in data["candidates"]}
    worst = {k: [0.0, 0.0] for k in labels}
    for s in data["scenes"]:
        ref = s["ref"]
        cells = [f"{ref['eta_cycle']:.6f}", f"{ref['dte_pp_um']:.3f}"] if ref else ["", ""]
        for r in s["results"]:
            if r["error"]:
                cells.append(f"failed: {r['error'][:80]}")
                worst[r["label"]] = [float("inf")] * 2
                continue
            mark = "" if r["ok"] or not checked[r["label"]] else " **FAILS**"
            cells.append(f"{fmt(r['d_eta'])} / {fmt(r['d_dte_um'])}{mark}")
            w = worst[r["label"]]
            w[0], w[1] = max(w[0], r["d_eta"]), max(w[1], r["d_dte_um"])
        L.append(f"| {s['scene']} | " + " | ".join(cells) + " |")
    L += ["", "Worst over the five scenes: " + "; ".join(
        f"{k} {fmt(e)} %-point / {fmt(x)} µm" for k, (e, x) in worst.items()) + ".", "",
          "Newmark's DTE is sampled at its own fixed steps, so its p-p includes the peaks it "
          "steps over (bench/wp_driver.py); the others at 64 samples per mesh cycle."]
    return L


def page(record, folder, _old=None):
    data = load(folder, record.data[0])
    m = data["meta"]
    provenance = (f"FMU: `{m['fmu']}`; run {m['run_at']} on {m['host']}, {m['seconds']:.0f} s.\n\n"
                  "The full model = varying mesh, thermal EHL friction, exact backlash (gear set "
                  f"1, OS265962). Candidates: the FMU's defaults ({m['defaults']}); "
                  "`solver = arkode_erk` at rtol 1e-4, atol 1e-8 m; the paper's fixed-step "
                  "Newmark (`solver = newmark`) at 50 steps per mesh cycle.")
    return head(record, provenance) + "\n" + "\n".join(cost(data) + [""] + accuracy(data)) + "\n"
