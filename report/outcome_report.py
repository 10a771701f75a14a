#!/usr/bin/env python3
"""An outcome study's pictures and page, from the files `proxsim study` wrote
in OUT for a study with `mode: outcomes`: results.csv, ranking.csv, pairs.csv,
selection.json and failures.csv.

  OUT/success_by_set.png/.svg    success rate of every set (rows) with every
                                 strategy (columns), the 95 % Wilson interval
                                 written in each cell
  OUT/failures_by_world.png/.svg how the failed runs ended (collided, fell,
                                 stopped where a way existed, time up), per
                                 world family (kind and difficulty), one panel
                                 per strategy
  OUT/price_success.png/.svg     price against success rate of every priced
                                 set and strategy, the Pareto front joined
  OUT/index.html                 links them, with the ranking, the cheapest
                                 set reaching the target and the replay
                                 commands of the first failures

Called by study_report.py (Debian's /usr/bin/python3 with python3-matplotlib).
"""
import csv
import html
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from proxsim_report.safe_files import save_figure, write_text  # noqa: E402  (never through a link)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def ordered(values):
    """The distinct values in the order first met (the study's order)."""
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    return seen


def answer_runs(results):
    """The runs the answer counts: the test worlds, each set's chosen variant
    of each strategy (every run when nothing is tuned)."""
    return [r for r in results if r.get("split", "test") == "test" and r.get("chosen", "1") == "1"]


def success_by_set(ranking, results, out):
    sets = ordered(r["set"] for r in results)
    strategies = ordered(r["strategy"] for r in results)
    grid = np.full((len(sets), len(strategies)), np.nan)
    text = {}
    for r in ranking:
        i, j = sets.index(r["set"]), strategies.index(r["strategy"])
        grid[i, j] = float(r["success_rate"])
        text[i, j] = (f"{float(r['success_rate']):.2f}\n[{float(r['success_ci95_low']):.2f}, "
                      f"{float(r['success_ci95_high']):.2f}]")
    fig, ax = plt.subplots(figsize=(2.2 + 1.8 * len(strategies), 1.2 + 0.55 * len(sets)), constrained_layout=True)
    image = ax.imshow(grid, cmap="RdYlGn", vmin=0, vmax=1, aspect="auto")
    for (i, j), label in text.items():
        ax.text(j, i, label, ha="center", va="center", fontsize=8)
    ax.set_xticks(range(len(strategies)), strategies)
    ax.set_yticks(range(len(sets)), [s if len(s) <= 40 else s[:37] + "..." for s in sets], fontsize=8)
    ax.set_xlabel("strategy")
    runs = ranking[0]["runs"] if ranking else "0"
    ax.set_title(f"Success rate by sensor set and strategy\n({runs} worlds each; 95 % Wilson interval)", fontsize=9)
    fig.colorbar(image, ax=ax, label="success rate")
    for ext in ("png", "svg"):
        save_figure(fig, os.path.join(out, f"success_by_set.{ext}"), dpi=120)
    plt.close(fig)


def failures_by_world(results, out):
    strategies = ordered(r["strategy"] for r in results)
    worlds = ordered(r["world"] for r in results)
    kinds = [("collided", "#d62728"), ("fell", "#9467bd"), ("stopped", "#ff7f0e"), ("time_up", "#7f7f7f")]
    fig, axes = plt.subplots(1, len(strategies), figsize=(1.5 + 2.6 * len(strategies), 3.6), squeeze=False,
                             constrained_layout=True, sharey=True)
    for k, strategy in enumerate(strategies):
        ax = axes[0][k]
        bottom = np.zeros(len(worlds))
        for outcome, colour in kinds:
            counts = []
            for w in worlds:
                rows = [r for r in results if r["strategy"] == strategy and r["world"] == w]
                failed = [r for r in rows if r["success"] == "0" and
                          (r["outcome"] == outcome or (outcome == "stopped" and r["outcome"] == "refused"))]
                counts.append(len(failed) / max(1, len(rows)))
            ax.bar(range(len(worlds)), counts, bottom=bottom, color=colour, label=outcome)
            bottom += np.array(counts)
        ax.set_xticks(range(len(worlds)), worlds, rotation=30, ha="right", fontsize=8)
        ax.set_title(f"strategy {strategy}", fontsize=9)
        ax.set_ylim(0, 1)
        if k == 0:
            ax.set_ylabel("share of runs that failed")
    axes[0][-1].legend(fontsize=7, loc="upper right")
    fig.suptitle("How the failed runs ended, by world family (every set; test worlds)", fontsize=10)
    for ext in ("png", "svg"):
        save_figure(fig, os.path.join(out, f"failures_by_world.{ext}"), dpi=120)
    plt.close(fig)


def price_success(ranking, selection, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.0), constrained_layout=True)
    strategies = ordered(r["strategy"] for r in ranking)
    markers = "osD^v<>"
    for k, strategy in enumerate(strategies):
        rows = [r for r in ranking if r["strategy"] == strategy and r["price_usd"] != ""]
        ax.scatter([float(r["price_usd"]) for r in rows], [float(r["success_rate"]) for r in rows],
                   marker=markers[k % len(markers)], label=strategy, alpha=0.8)
    front = selection["pareto_front"]
    if front:
        ax.plot([p["price_usd"] for p in front], [p["success_rate"] for p in front], "k--", lw=1, label="Pareto front")
    ax.axhline(selection["target_success"], color="#2ca02c", lw=0.8, ls=":", label="target")
    ax.set_xlabel("price of the set (USD)")
    ax.set_ylabel("success rate")
    ax.set_ylim(-0.02, 1.05)
    ax.legend(fontsize=8)
    ax.set_title("Price against success", fontsize=10)
    for ext in ("png", "svg"):
        save_figure(fig, os.path.join(out, f"price_success.{ext}"), dpi=120)
    plt.close(fig)


def page(ranking, selection, failures, out):
    def table(rows, keys):
        head = "".join(f"<th>{html.escape(k)}</th>" for k in keys)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(str(r.get(k, '')))}</td>" for k in keys) + "</tr>"
                       for r in rows)
        return f"<table><tr>{head}</tr>{body}</table>"

    cheapest = selection["cheapest_reaching_target"]
    answer = ("no priced set reaches it" if cheapest is None else
              f"<b>{html.escape(cheapest['set'])}</b> with {html.escape(cheapest['strategy'])}, "
              f"${cheapest['price_usd']:.2f}, success {cheapest['success_rate']:.3f} "
              f"[{cheapest['success_ci95'][0]:.3f}, {cheapest['success_ci95'][1]:.3f}]")
    # where the worlds or the strategy, not the sensors, limit the answer (the baselines say so)
    warnings = "".join(f"<li>{html.escape(w)}</li>" for w in selection.get("warnings", []))
    warnings = f'<h2>Warnings</h2><ul class="warn">{warnings}</ul>' if warnings else ""
    lowest = selection.get("lowest_expected_cost")
    lowest = ("" if lowest is None else
              f"<p>Lowest expected cost per run: <b>{html.escape(lowest['set'])}</b> with "
              f"{html.escape(lowest['strategy'])}, ${lowest['expected_cost_per_run_usd']:.3f} a run.</p>")
    text = f"""<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>proxsim outcome study</title>
<style>body{{font-family:sans-serif;margin:2em;max-width:1100px}} table{{border-collapse:collapse;font-size:13px}}
td,th{{border:1px solid #ccc;padding:3px 6px}} img{{max-width:100%}} .warn{{color:#a0522d}}</style></head><body>
<h1>Closed-loop study: which sensors get the robot through</h1>
<p>Files: <a href="results.csv">results.csv</a> (one row per run), <a href="ranking.csv">ranking.csv</a>,
<a href="pairs.csv">pairs.csv</a> (McNemar), <a href="selection.json">selection.json</a>,
<a href="failures.csv">failures.csv</a> (replay commands).</p>
{warnings}
<h2>Cheapest set reaching a success rate of {selection['target_success']}</h2><p>{answer}</p>{lowest}
<p>{html.escape(selection['success'])}.</p>
<h2>Success by set and strategy</h2><img src="success_by_set.png" alt="success by set and strategy">
<h2>Failures by world</h2><img src="failures_by_world.png" alt="failures by world family">
<h2>Price against success</h2><img src="price_success.png" alt="price against success">
<h2>Ranking</h2>
{table(ranking[:30], ["rank", "set", "strategy", "tuned", "price_usd", "runs", "success_rate", "success_ci95_low",
                      "success_ci95_high", "perception_score", "expected_cost_per_run_usd", "collision_rate", "fall_rate", "stopped_rate", "median_time_to_goal_s",
                      "median_path_ratio", "min_clearance_m"])}
<h2>Failed runs (first 30 of {len(failures)})</h2>
{table(failures[:30], ["set", "strategy", "tuned", "world", "seed", "outcome", "outcome_t_s", "command"])}
</body></html>
"""
    write_text(os.path.join(out, "index.html"), text)


def draw(out):
    results = answer_runs(read_csv(os.path.join(out, "results.csv")))
    ranking = read_csv(os.path.join(out, "ranking.csv"))
    failures = read_csv(os.path.join(out, "failures.csv"))
    with open(os.path.join(out, "selection.json")) as f:
        selection = json.load(f)
    if results:
        success_by_set(ranking, results, out)
        failures_by_world(results, out)
    price_success(ranking, selection, out)
    page(ranking, selection, failures, out)
