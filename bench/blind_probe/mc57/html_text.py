"""Print the visible text of an sinsim HTML report (SVGs replaced by [SVG n: #paths, #polylines, #text]). usage: html_text.py FILE"""
import re, html, sys
s = open(sys.argv[1]).read()
n = [0]
def svg(m):
    n[0] += 1; b = m.group(0)
    return f"[SVG {n[0]}: {b.count('<path')} paths, {b.count('<polyline')} polylines, {b.count('<polygon')} polygons, {len(b)} chars]"
s = re.sub(r'<svg.*?</svg>\s*</svg>|<svg.*?</svg>', svg, s, flags=re.S)
s = re.sub(r'<style.*?</style>', '', s, flags=re.S)
s = re.sub(r'</t[dh]>', ' | ', s); s = re.sub(r'<(tr|p|h\d|li|br|table|pre|figcaption)[^>]*>', '\n', s)
s = re.sub(r'<[^>]+>', '', s); s = html.unescape(s); s = re.sub(r'\n\s*\n+', '\n', s)
print(s)
