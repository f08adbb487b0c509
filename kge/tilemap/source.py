"""A map and every file it names, read into one document in Tiled's JSON structure.

TMX/TSX/TX files go through :mod:`kge.tilemap.tmx`; JSON files (TMJ/TSJ/TJ and
the older ``.json``) are read here and normalised: what Tiled versions before
1.9 wrote differently (``type`` for ``class``, properties as a dict, tiles as
a dict keyed by id, ``tileproperties``) becomes the current shape, so the
builder reads one structure. External tilesets and templates are read once
each, through the confined :class:`~kge.tilemap.files.MapReader`; a template
that names itself (directly or not) is refused.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from kge.tilemap import tmx
from kge.tilemap.errors import TilemapError
from kge.tilemap.files import MapReader


def _is_json(path: Path, text: str) -> bool:
    return path.suffix.lower() in (".json", ".tmj", ".tsj", ".tj") or text.lstrip()[:1] == "{"


def _load_json(text: str, where: str) -> Any:
    try:
        return json.loads(text)
    except RecursionError:
        raise TilemapError(f"{where}: JSON nests too deeply to be a Tiled file") from None
    except ValueError as exc:
        raise TilemapError(f"{where}: not valid JSON ({exc})") from None


def _props(value: Any, types: Any = None) -> list[dict[str, Any]]:
    """Properties as a list of {name, type, value} (Tiled < 1.2 JSON wrote a dict)."""
    if isinstance(value, dict):
        types = types if isinstance(types, dict) else {}
        return [{"name": k, "type": types.get(k, "string"), "value": v} for k, v in value.items()]
    return value if isinstance(value, list) else []


def _object(o: Any, where: str) -> dict[str, Any]:
    if not isinstance(o, dict):
        raise TilemapError(f"{where}: an object is {type(o).__name__}, not a JSON object")
    if "type" in o and "class" not in o:
        o["class"] = o.pop("type")
    o["properties"] = _props(o.get("properties"), o.get("propertytypes"))
    return o


def _json_layers(layers: Any, depth: int, max_nesting: int, where: str) -> list[Any]:
    if depth > max_nesting:
        raise TilemapError(
            f"{where}: group layers nest deeper than {max_nesting} "
            "(MapLimits.nesting; pass load_map(..., limits=MapLimits(nesting=...)) to allow more)"
        )
    if not isinstance(layers, list):
        raise TilemapError(f"{where}: 'layers' is {type(layers).__name__}, not a list")
    for d in layers:
        if not isinstance(d, dict):
            raise TilemapError(f"{where}: a layer is {type(d).__name__}, not a JSON object")
        d["properties"] = _props(d.get("properties"), d.get("propertytypes"))
        if d.get("type") == "tilelayer":
            if "data" in d:
                d["data"] = _json_data(d, d["data"])
            for ch in d.get("chunks") or []:
                if isinstance(ch, dict):
                    ch["data"] = _json_data(d, ch.get("data"))
        elif d.get("type") == "objectgroup":
            d["objects"] = [_object(o, where) for o in d.get("objects") or []]
        elif d.get("type") == "group":
            d["layers"] = _json_layers(d.get("layers") or [], depth + 1, max_nesting, where)
    return layers


def _json_data(layer: dict[str, Any], data: Any) -> Any:
    if isinstance(data, str):
        return {
            "encoding": layer.get("encoding", "base64"),
            "compression": layer.get("compression", ""),
            "text": data,
        }
    return data


def _json_tileset(d: Any, where: str) -> dict[str, Any]:
    if not isinstance(d, dict):
        raise TilemapError(f"{where}: a tileset is {type(d).__name__}, not a JSON object")
    d["properties"] = _props(d.get("properties"), d.get("propertytypes"))
    tiles = d.get("tiles")
    if isinstance(tiles, dict):  # Tiled < 1.2: {"id": {...}}
        tiles = [{"id": int(k), **v} for k, v in tiles.items() if isinstance(v, dict)]
    tiles = list(tiles or [])
    by_id = {t.get("id"): t for t in tiles if isinstance(t, dict)}
    old_props = d.pop("tileproperties", None)  # Tiled < 1.2
    if isinstance(old_props, dict):
        types = d.pop("tilepropertytypes", None) or {}
        for k, v in old_props.items():
            t = by_id.setdefault(int(k), {"id": int(k)})
            t["properties"] = _props(v, types.get(k))
    for t in by_id.values():
        if not isinstance(t, dict):
            raise TilemapError(f"{where}: a tile is {type(t).__name__}, not a JSON object")
        if "type" in t and "class" not in t:
            t["class"] = t.pop("type")
        t["properties"] = _props(t.get("properties"), t.get("propertytypes"))
        og = t.get("objectgroup")
        if isinstance(og, dict):
            og["objects"] = [_object(o, where) for o in og.get("objects") or []]
    d["tiles"] = list(by_id.values())
    return d


class MapSource:
    """Reads the map file and what it names; ``doc`` is the whole map as one dict."""

    def __init__(self, reader: MapReader) -> None:
        self.reader = reader
        self.path = reader.map
        self._templates: dict[Path, dict[str, Any]] = {}
        self._tilesets: dict[Path, dict[str, Any]] = {}
        text = reader.read_text(self.path, what="map file")
        where = str(self.path)
        nest = reader.limits.nesting
        if _is_json(self.path, text):
            doc = _load_json(text, where)
            if not isinstance(doc, dict) or doc.get("type", "map") != "map":
                raise TilemapError(f"{where}: not a Tiled map (no JSON map object)")
            doc["properties"] = _props(doc.get("properties"), doc.get("propertytypes"))
            doc["layers"] = _json_layers(doc.get("layers") or [], 0, nest, where)
            sets = doc.get("tilesets") or []
            if not isinstance(sets, list):
                raise TilemapError(f"{where}: 'tilesets' is not a list")
            doc["tilesets"] = [
                t if isinstance(t, dict) and "source" in t else _json_tileset(t, where)
                for t in sets
            ]
        else:
            doc = tmx.map_doc(tmx.parse_xml(text, where), max_nesting=nest, where=where)
        for ts in doc["tilesets"]:
            if not isinstance(ts, dict):
                raise TilemapError(f"{where}: a tileset entry is not an object")
            if "source" in ts:
                ext = self.tileset(self.path, str(ts["source"]))
                ts.update({k: v for k, v in ext.items() if k != "firstgid"})
                ts.pop("source")
            else:
                ts["_file"] = self.path
        self.doc = doc

    def tileset(self, owner: Path, name: str) -> dict[str, Any]:
        """An external tileset (TSX or TSJ) named in ``owner``; ``_file`` is where it is."""
        path = self.reader.resolve(owner, name)
        if path not in self._tilesets:
            text = self.reader.read_text(path, owner, "tileset")
            where = str(path)
            if _is_json(path, text):
                d = _json_tileset(_load_json(text, where), where)
            else:
                root = tmx.parse_xml(text, where)
                if root.tag != "tileset":
                    raise TilemapError(f"{where}: not a Tiled tileset (root <{root.tag}>)")
                d = tmx.tileset_doc(root, where)
            d["_file"] = path
            self._tilesets[path] = d
        return dict(self._tilesets[path])

    def template(self, owner: Path, name: str, chain: tuple[Path, ...] = ()) -> dict[str, Any]:
        """A template (TX or TJ): {"object": ..., "tileset": {...} | absent, "_file": path}."""
        path = self.reader.resolve(owner, name)
        if path in chain:
            loop = " -> ".join(str(p) for p in (*chain, path))
            raise TilemapError(f"{self.path}: template loop: {loop}")
        if path not in self._templates:
            text = self.reader.read_text(path, owner, "template")
            where = str(path)
            if _is_json(path, text):
                d = _load_json(text, where)
                if not isinstance(d, dict) or not isinstance(d.get("object"), dict):
                    raise TilemapError(f"{where}: not a Tiled template (no 'object')")
                d["object"] = _object(d["object"], where)
            else:
                d = tmx.template_doc(tmx.parse_xml(text, where), where)
            d["_file"] = path
            inner = d["object"].get("template")
            if inner:  # Tiled never nests templates; a file that does must not loop
                base = self.template(path, str(inner), (*chain, path))
                d["object"] = {**base["object"], **d["object"]}
                d["object"].pop("template", None)
                d.setdefault("tileset", base.get("tileset"))
            ts = d.get("tileset")
            if isinstance(ts, dict) and ts.get("source"):
                ts["_path"] = self.reader.resolve(path, str(ts["source"]))
            self._templates[path] = d
        return self._templates[path]
