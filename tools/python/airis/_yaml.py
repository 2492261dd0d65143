"""Writes a Python dict as block YAML, one key per line, so scene errors name useful lines."""

import math

__all__ = ["dump", "flow"]


def _scalar(value):
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return ".nan"
        if math.isinf(value):
            return ".inf" if value > 0 else "-.inf"
        return repr(value)
    if hasattr(value, "item") and callable(value.item):  # numpy scalars
        return _scalar(value.item())
    text = str(value)
    # Quoted (JSON escapes are valid YAML double-quoted escapes) so no text is read as another type.
    import json
    return json.dumps(text)


def _is_flat_list(value):
    return all(not isinstance(v, (dict, list, tuple)) for v in value)


def _emit(value, indent, lines):
    pad = " " * indent
    if isinstance(value, dict):
        if not value:
            lines[-1] += " {}"
            return
        for key, v in value.items():
            if not isinstance(key, str):
                raise TypeError(f"scene dict keys must be strings (got {key!r})")
            lines.append(f"{pad}{key}:")
            _child(v, indent, lines)
        return
    raise TypeError(f"expected a dict (got {type(value).__name__})")


def _child(v, indent, lines):
    if isinstance(v, dict):
        if not v:
            lines[-1] += " {}"
        else:
            _emit(v, indent + 2, lines)
    elif isinstance(v, (list, tuple)) or getattr(v, "ndim", 0) > 0:  # lists, numpy arrays
        items = v.tolist() if hasattr(v, "tolist") else list(v)
        if _is_flat_list(items):
            lines[-1] += " [" + ", ".join(_scalar(x) for x in items) + "]"
            return
        for item in items:
            lines.append(" " * (indent + 2) + "-")
            if isinstance(item, dict):
                first = True
                for key, sub in item.items():
                    if first:
                        lines[-1] += f" {key}:"
                        first = False
                    else:
                        lines.append(" " * (indent + 4) + f"{key}:")
                    _child(sub, indent + 4, lines)
                if first:
                    lines[-1] += " {}"
            elif isinstance(item, (list, tuple)):
                lines[-1] += " [" + ", ".join(_scalar(x) for x in item) + "]"
            else:
                lines[-1] += " " + _scalar(item)
    else:
        lines[-1] += " " + _scalar(v)


def flow(value):
    """One value as flow YAML: a scalar, or a list (nested lists, numpy arrays) as `[a, b]`."""
    if isinstance(value, dict):
        raise TypeError("expected a value or a list (got a dict: set its keys one by one)")
    if isinstance(value, (list, tuple)) or getattr(value, "ndim", 0) > 0:
        items = value.tolist() if hasattr(value, "tolist") else list(value)
        return "[" + ", ".join(flow(x) for x in items) + "]"
    return _scalar(value)


def dump(data):
    """Block YAML for a dict of dicts, lists and scalars (numpy arrays and scalars too)."""
    lines = []
    _emit(data, 0, lines)
    return "\n".join(lines) + "\n"
