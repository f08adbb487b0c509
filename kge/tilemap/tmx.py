"""Tiled's XML files (TMX maps, TSX tilesets, TX templates) as Tiled's JSON structure.

One reader builds kge's map data (:mod:`kge.tilemap.parse`); this module turns
the XML flavour into the dicts Tiled's JSON flavour holds, so every later step
exists once. Attribute names follow the JSON keys (``tintcolor``,
``parallaxx``...); what a file omits is left out, and the reader applies
Tiled's defaults. Tile data stays text here (decoded with limits later).

>>> doc = map_doc(ElementTree.fromstring(
...     '<map width="2" height="1" tilewidth="8" tileheight="8" orientation="orthogonal">'
...     '<layer name="a" width="2" height="1"><data encoding="csv">1,0</data></layer></map>'),
...     max_nesting=10, where="m.tmx")
>>> doc["layers"][0]["type"], doc["layers"][0]["data"]
('tilelayer', {'encoding': 'csv', 'compression': '', 'text': '1,0'})
"""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from typing import Any

from kge.tilemap.errors import TilemapError

_INT = {
    "width",
    "height",
    "tilewidth",
    "tileheight",
    "hexsidelength",
    "nextlayerid",
    "nextobjectid",
    "compressionlevel",
    "firstgid",
    "tilecount",
    "columns",
    "spacing",
    "margin",
    "id",
    "gid",
    "tileid",
    "duration",
    "startx",
    "starty",
}
_FLOAT = {
    "x",
    "y",
    "opacity",
    "offsetx",
    "offsety",
    "parallaxx",
    "parallaxy",
    "rotation",
    "parallaxoriginx",
    "parallaxoriginy",
    "probability",
    "imagewidth",
    "imageheight",
}
_BOOL = {"visible", "infinite", "repeatx", "repeaty", "locked"}
_LAYERS = {"layer", "objectgroup", "imagelayer", "group"}
_TYPES = {
    "layer": "tilelayer",
    "objectgroup": "objectgroup",
    "imagelayer": "imagelayer",
    "group": "group",
}


def _value(key: str, text: str, where: str) -> Any:
    try:
        if key in _INT:
            try:
                return int(text)
            except ValueError:
                return float(text)  # objects' sizes are floats; the reader checks ints
        if key in _FLOAT:
            return float(text)
        if key in _BOOL:
            return text.strip() not in ("0", "false", "")
    except ValueError:
        raise TilemapError(f"{where}: attribute {key}={text!r} is not a number") from None
    return text


def _attrs(el: ElementTree.Element, where: str) -> dict[str, Any]:
    return {k: _value(k, v, where) for k, v in el.attrib.items()}


def properties(el: ElementTree.Element | None, where: str) -> list[dict[str, Any]]:
    """``<properties>`` as JSON's list of {name, type, value} (class values nested)."""
    if el is None:
        return []
    out = []
    for p in el.findall("property"):
        ptype = p.get("type", "string")
        if ptype == "class":
            value: Any = {q["name"]: q["value"] for q in properties(p.find("properties"), where)}
        else:
            value = p.get("value")
            if value is None:
                value = p.text or ""
        out.append({"name": p.get("name", ""), "type": ptype, "value": value})
    return out


def _image(el: ElementTree.Element | None, out: dict[str, Any], where: str) -> None:
    if el is None:
        return
    if el.find("data") is not None:
        raise TilemapError(
            f"{where}: an image embedded in the file (<image><data>) is not supported; "
            "save the image as a file next to the map"
        )
    out["image"] = el.get("source", "")
    for k, jk in (("width", "imagewidth"), ("height", "imageheight")):
        if el.get(k) is not None:
            out[jk] = _value("imagewidth", el.get(k, ""), where)
    if el.get("trans"):
        out["transparentcolor"] = el.get("trans")


def _objects(el: ElementTree.Element, where: str) -> list[dict[str, Any]]:
    out = []
    for o in el.findall("object"):
        d = _attrs(o, where)
        if "type" in d and "class" not in d:
            d["class"] = d.pop("type")  # Tiled < 1.9 wrote "type"
        d["properties"] = properties(o.find("properties"), where)
        if o.find("ellipse") is not None:
            d["ellipse"] = True
        if o.find("point") is not None:
            d["point"] = True
        for kind in ("polygon", "polyline"):
            poly = o.find(kind)
            if poly is not None:
                d[kind] = _points(poly.get("points", ""), where)
        text = o.find("text")
        if text is not None:
            t = _attrs(text, where)
            t["text"] = text.text or ""
            d["text"] = t
        out.append(d)
    return out


def _points(text: str, where: str) -> list[dict[str, float]]:
    pts = []
    for pair in text.split():
        xy = pair.split(",")
        try:
            pts.append({"x": float(xy[0]), "y": float(xy[1])})
        except (ValueError, IndexError):
            raise TilemapError(f"{where}: polygon point {pair!r} is not 'x,y'") from None
    return pts


def _data(el: ElementTree.Element, where: str) -> dict[str, Any]:
    enc = el.get("encoding", "")
    comp = el.get("compression", "")
    if enc == "":
        gids = [t.get("gid", "0") for t in el.findall("tile")]  # Tiled's oldest XML data
        return {"encoding": "csv", "compression": "", "text": ",".join(gids)}
    return {"encoding": enc, "compression": comp, "text": el.text or ""}


def _layer(el: ElementTree.Element, depth: int, max_nesting: int, where: str) -> dict[str, Any]:
    d = _attrs(el, where)
    if "class" not in d and "type" in d:
        d["class"] = d.pop("type")
    d["type"] = _TYPES[el.tag]
    d["properties"] = properties(el.find("properties"), where)
    if el.tag == "layer":
        data = el.find("data")
        if data is not None:
            chunks = data.findall("chunk")
            if chunks:
                enc, comp = data.get("encoding", ""), data.get("compression", "")
                d["chunks"] = []
                for ch in chunks:
                    c = _attrs(ch, where)
                    ch.set("encoding", enc)
                    ch.set("compression", comp)
                    c["data"] = _data(ch, where)
                    d["chunks"].append(c)
            else:
                d["data"] = _data(data, where)
    elif el.tag == "objectgroup":
        d["objects"] = _objects(el, where)
    elif el.tag == "imagelayer":
        _image(el.find("image"), d, where)
    else:
        d["layers"] = layers(el, depth + 1, max_nesting, where)
    return d


def layers(el: ElementTree.Element, depth: int, max_nesting: int, where: str) -> list[Any]:
    if depth > max_nesting:
        raise TilemapError(
            f"{where}: group layers nest deeper than {max_nesting} "
            "(MapLimits.nesting; pass load_map(..., limits=MapLimits(nesting=...)) to allow more)"
        )
    return [_layer(c, depth, max_nesting, where) for c in el if c.tag in _LAYERS]


def tileset_doc(el: ElementTree.Element, where: str) -> dict[str, Any]:
    """A ``<tileset>`` element (embedded or a TSX root) as Tiled's JSON tileset."""
    d = _attrs(el, where)
    d["properties"] = properties(el.find("properties"), where)
    _image(el.find("image"), d, where)
    off = el.find("tileoffset")
    if off is not None:
        d["tileoffset"] = {"x": int(float(off.get("x", 0))), "y": int(float(off.get("y", 0)))}
    grid = el.find("grid")
    if grid is not None:
        d["grid"] = _attrs(grid, where)
    tiles = []
    for t in el.findall("tile"):
        td = _attrs(t, where)
        if "type" in td and "class" not in td:
            td["class"] = td.pop("type")
        td["properties"] = properties(t.find("properties"), where)
        _image(t.find("image"), td, where)
        og = t.find("objectgroup")
        if og is not None:
            td["objectgroup"] = {"objects": _objects(og, where)}
        anim = t.find("animation")
        if anim is not None:
            td["animation"] = [_attrs(f, where) for f in anim.findall("frame")]
        tiles.append(td)
    d["tiles"] = tiles
    terrains = el.find("terraintypes")  # Tiled 0.9 - 1.4
    if terrains is not None:
        d["terrains"] = [_attrs(t, where) for t in terrains.findall("terrain")]
    ws = el.find("wangsets")
    if ws is not None:
        d["wangsets"] = [_wangset(w, where) for w in ws.findall("wangset")]
    return d


def _wangset(el: ElementTree.Element, where: str) -> dict[str, Any]:
    d = _attrs(el, where)
    d["colors"] = [_attrs(c, where) for c in el.findall("wangcolor")]
    d["cornercolors"] = [_attrs(c, where) for c in el.findall("wangcornercolor")]  # 1.1-1.4
    d["edgecolors"] = [_attrs(c, where) for c in el.findall("wangedgecolor")]  # 1.1-1.4
    d["wangtiles"] = [_attrs(t, where) for t in el.findall("wangtile")]
    return d


def map_doc(root: ElementTree.Element, *, max_nesting: int, where: str) -> dict[str, Any]:
    """A ``<map>`` root as Tiled's JSON map (tilesets embedded or ``source`` refs)."""
    if root.tag != "map":
        raise TilemapError(f"{where}: not a Tiled map (the root element is <{root.tag}>)")
    d = _attrs(root, where)
    d["properties"] = properties(root.find("properties"), where)
    d["tilesets"] = []
    for ts in root.findall("tileset"):
        if ts.get("source") is not None:
            d["tilesets"].append(
                {
                    "firstgid": _value("firstgid", ts.get("firstgid", "1"), where),
                    "source": ts.get("source"),
                }
            )
        else:
            d["tilesets"].append(tileset_doc(ts, where))
    d["layers"] = layers(root, 0, max_nesting, where)
    return d


def template_doc(root: ElementTree.Element, where: str) -> dict[str, Any]:
    """A ``<template>`` (TX) root: {"tileset": {...} or None, "object": {...}}."""
    if root.tag != "template":
        raise TilemapError(f"{where}: not a Tiled template (the root element is <{root.tag}>)")
    out: dict[str, Any] = {}
    ts = root.find("tileset")
    if ts is not None:
        out["tileset"] = {
            "firstgid": _value("firstgid", ts.get("firstgid", "1"), where),
            "source": ts.get("source", ""),
        }
    objs = _objects(root, where)
    if not objs:
        raise TilemapError(f"{where}: the template holds no <object>")
    out["object"] = objs[0]
    return out


def parse_xml(text: str, where: str) -> ElementTree.Element:
    """Parse XML text; DTDs and entities are refused (no entity expansion bombs)."""
    if "<!DOCTYPE" in text or "<!ENTITY" in text:
        raise TilemapError(f"{where}: XML with a DOCTYPE or entities is not a Tiled file")
    try:
        return ElementTree.fromstring(text)
    except ElementTree.ParseError as exc:
        raise TilemapError(f"{where}: not well-formed XML ({exc})") from None
