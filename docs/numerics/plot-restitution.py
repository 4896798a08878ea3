#!/usr/bin/env python3
"""Plots docs/numerics/restitution-ring2d-e*.csv (from `elastic-lab-cli restitution`) as one SVG:
rebound / impact speed against impact speed (log axis), a free particle (solid) and the ring's
centre of mass (dashed) for each restitution e, with e itself as a dotted line."""
import csv, math, os, sys

out_dir = os.path.dirname(os.path.abspath(__file__))
files = sorted(f for f in os.listdir(out_dir) if f.startswith("restitution-ring2d-e") and f.endswith(".csv"))
W, H, L, R, T, B = 640, 400, 60, 150, 30, 50
x0, x1 = math.log10(0.2), math.log10(50.0)
def px(v): return L + (math.log10(v) - x0) / (x1 - x0) * (W - L - R)
def py(r): return T + (1.0 - r) * (H - T - B)
colors = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"]
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>',
       f'<text x="{W/2}" y="18" text-anchor="middle">ring2d: rebound / impact speed (weightless), contact = force</text>']
for v in [0.3, 1, 3, 10, 30]:
    svg.append(f'<line x1="{px(v):.1f}" y1="{T}" x2="{px(v):.1f}" y2="{H-B}" stroke="#ddd"/>')
    svg.append(f'<text x="{px(v):.1f}" y="{H-B+16}" text-anchor="middle">{v}</text>')
for r in [0, 0.2, 0.4, 0.6, 0.8, 1.0]:
    svg.append(f'<line x1="{L}" y1="{py(r):.1f}" x2="{W-R}" y2="{py(r):.1f}" stroke="#ddd"/>')
    svg.append(f'<text x="{L-6}" y="{py(r)+4:.1f}" text-anchor="end">{r:.1f}</text>')
svg.append(f'<text x="{(L+W-R)/2}" y="{H-12}" text-anchor="middle">impact speed [m/s]</text>')
for k, name in enumerate(files):
    rows = list(csv.DictReader(open(os.path.join(out_dir, name))))
    c = colors[k % len(colors)]
    e = float(rows[0]["e_set"])
    for key, dash in (("particle", ""), ("body", ' stroke-dasharray="6,4"')):
        pts = [(float(r["speed"]), float(r[key])) for r in rows if float(r[key]) >= 0.0]
        if len(pts) > 1:
            path = " ".join(f"{px(s):.1f},{py(v):.1f}" for s, v in pts)
            svg.append(f'<polyline points="{path}" fill="none" stroke="{c}" stroke-width="2"{dash}/>')
    svg.append(f'<line x1="{L}" y1="{py(e):.1f}" x2="{W-R}" y2="{py(e):.1f}" stroke="{c}" stroke-dasharray="1,3"/>')
    y = T + 20 + 18 * k
    svg.append(f'<line x1="{W-R+10}" y1="{y}" x2="{W-R+30}" y2="{y}" stroke="{c}" stroke-width="2"/>')
    svg.append(f'<text x="{W-R+35}" y="{y+4}">e = {e:g}</text>')
y = T + 20 + 18 * len(files) + 10
svg.append(f'<text x="{W-R+10}" y="{y}">solid: a particle</text>')
svg.append(f'<text x="{W-R+10}" y="{y+16}">dashed: the ring</text>')
svg.append(f'<text x="{W-R+10}" y="{y+32}">dotted: e</text>')
svg.append("</svg>")
open(os.path.join(out_dir, "restitution-ring2d.svg"), "w").write("\n".join(svg) + "\n")
