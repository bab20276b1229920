#!/usr/bin/env python3
"""Moves translations between Qt Linguist .ts files and JSON lists.

  tsjson.py dump TS OUT.json      messages of TS that are unfinished (or empty), as a JSON list of
                                  {"context","source","comment","numerus","where"}
  tsjson.py fill TS IN.json...    writes the translations of the JSON files into TS: an object
                                  with "translation" (a string, or a list of plural forms when
                                  "numerus" is true) fills the message with the same
                                  context+source+comment and marks it finished
  tsjson.py stats TS              counts finished / unfinished / vanished messages
"""
import json, sys
import xml.etree.ElementTree as ET

def key(ctx, src, com):
    return (ctx, src, com or "")

def messages(root):
    for c in root.iter("context"):
        ctx = c.findtext("name")
        for m in c.iter("message"):
            yield ctx, m

def dump(ts, out):
    root = ET.parse(ts).getroot()
    res = []
    for ctx, m in messages(root):
        t = m.find("translation")
        if t.get("type") in ("vanished", "obsolete"):
            continue
        if t.get("type") == "unfinished" or not (t.text or list(t)):
            loc = m.find("location")
            res.append({"context": ctx, "source": m.findtext("source"),
                        "comment": m.findtext("comment") or "",
                        "numerus": m.get("numerus") == "yes",
                        "where": (loc.get("filename").split("/src/")[-1] + ":" + loc.get("line")) if loc is not None else ""})
    json.dump(res, open(out, "w"), ensure_ascii=False, indent=1)
    print(f"{len(res)} unfinished messages -> {out}")

def fill(ts, inputs):
    tree = ET.parse(ts)
    root = tree.getroot()
    tr = {}
    by_source = {}  # the same text moved to another context keeps its translation
    for f in inputs:
        for o in json.load(open(f)):
            if "translation" in o and o["translation"] not in ("", None, []):
                tr[key(o["context"], o["source"], o.get("comment"))] = o["translation"]
                by_source.setdefault((o["source"], o.get("comment") or ""), o["translation"])
    n = 0
    for ctx, m in messages(root):
        k = key(ctx, m.findtext("source"), m.findtext("comment"))
        if k not in tr:
            alt = (m.findtext("source"), m.findtext("comment") or "")
            if alt not in by_source:
                continue
            tr[k] = by_source[alt]
        t = m.find("translation")
        if t.get("type") in ("vanished", "obsolete"):
            continue
        v = tr[k]
        for child in list(t):
            t.remove(child)
        t.text = None
        if m.get("numerus") == "yes":
            forms = v if isinstance(v, list) else [v]
            for f in forms:
                e = ET.SubElement(t, "numerusform")
                e.text = f
        else:
            t.text = v if isinstance(v, str) else v[0]
        if "type" in t.attrib:
            del t.attrib["type"]
        n += 1
    ET.indent(tree, space="    ")
    with open(ts, "wb") as fh:
        fh.write(b'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
        tree.write(fh, encoding="utf-8", xml_declaration=False)
        fh.write(b"\n")
    print(f"filled {n} messages of {ts}")

def stats(ts):
    root = ET.parse(ts).getroot()
    c = {"finished": 0, "unfinished": 0, "vanished": 0}
    for ctx, m in messages(root):
        t = m.find("translation")
        ty = t.get("type")
        if ty in ("vanished", "obsolete"):
            c["vanished"] += 1
        elif ty == "unfinished" or not (t.text or list(t)):
            c["unfinished"] += 1
        else:
            c["finished"] += 1
    print(ts, c)

if __name__ == "__main__":
    cmd = sys.argv[1]
    if cmd == "dump": dump(sys.argv[2], sys.argv[3])
    elif cmd == "fill": fill(sys.argv[2], sys.argv[3:])
    elif cmd == "stats": stats(sys.argv[2])
    else: sys.exit(__doc__)
