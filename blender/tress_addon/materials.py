"""Blender materials as tress materials (``docs/scene-format.md``, "Materials").

The mapping works on plain values (a node's type, its input values and properties), so it
is testable without Blender; :func:`from_material` reads them from a ``bpy`` material.

Principled Hair BSDF, Chiang model, to tress's ``physical`` hair (the same model, Chiang
et al. 2016):

============================  ==============================================================
Blender                       tress
============================  ==============================================================
Melanin ``m``, Redness ``r``  ``eumelanin = -ln(1 - m) (1 - r)``, ``pheomelanin = -ln(1 - m) r``
                              (melanin as a concentration, as Blender's manual defines it;
                              both use the same absorption coefficients per unit)
Direct Coloring: Color        ``color``
Absorption Coefficient ``σ``  ``color = exp(-sqrt(σ) · p(β_n))``: the colour whose inversion
                              (Chiang §4.2, the polynomial p of radial roughness) gives σ
Roughness                     ``beta_m``
Radial Roughness              ``beta_n``
Offset (radians)              ``alpha`` (degrees)
IOR                           ``eta``
Coat, Tint, Random Color,     not mapped (a warning names each one that is not at its
Random Roughness              neutral value)
============================  ==============================================================

Other shaders map to the nearest tress material: Principled BSDF and Diffuse BSDF to
``diffuse`` with the base colour (metallic 1 or Glossy BSDF to ``mirror``, transmission 1
or Glass BSDF to ``glass`` with the IOR), Hair BSDF (Kajiya-Kay) to ``tube``; anything
else to ``diffuse`` with the material's viewport colour, with a warning.
"""

from __future__ import annotations

import math
import sys
from typing import Any, Mapping

# Roughness must be in (0, 1] for tress.
_MIN_BETA = 1e-3


def _clamp(x: float, lo: float, hi: float) -> float:
    return max(lo, min(hi, float(x)))


def color_polynomial(beta_n: float) -> float:
    """Chiang et al. 2016, §4.2: the polynomial that relates absorption to colour."""
    b = beta_n
    return 5.969 - 0.215 * b + 2.532 * b**2 - 10.73 * b**3 + 5.574 * b**4 + 0.245 * b**5


def rgb(v: Any) -> list[float]:
    return [float(c) for c in list(v)[:3]]


def principled_hair(inputs: Mapping[str, Any], parametrization: str, model: str = "CHIANG", name: str = "hair"):
    """The tress material for a Principled Hair BSDF with these input values, and the
    warnings for what is not mapped."""
    warnings = []
    if model != "CHIANG":
        warnings.append(f"material {name}: the {model.title()} hair model is rendered with the Chiang model's inputs")
    beta_m = _clamp(inputs.get("Roughness", 0.3), _MIN_BETA, 1.0)
    beta_n = _clamp(inputs.get("Radial Roughness", 0.3), _MIN_BETA, 1.0)
    out: dict[str, Any] = {"type": "physical"}
    if parametrization == "MELANIN":
        m = _clamp(inputs.get("Melanin", 0.8), 0.0, 0.9999)
        red = _clamp(inputs.get("Melanin Redness", 1.0), 0.0, 1.0)
        quantity = -math.log(1.0 - m)
        out["eumelanin"] = quantity * (1.0 - red)
        out["pheomelanin"] = quantity * red
        tint = rgb(inputs.get("Tint", (1.0, 1.0, 1.0)))
        if any(abs(c - 1.0) > 1e-6 for c in tint):
            warnings.append(f"material {name}: Tint {tint} is not mapped (tress has no tint)")
    elif parametrization == "COLOR":
        out["color"] = [_clamp(c, 0.0, 1.0) for c in rgb(inputs.get("Color", (0.017, 0.005, 0.002)))]
    elif parametrization == "ABSORPTION":
        sigma = [max(0.0, c) for c in rgb(inputs.get("Absorption Coefficient", (0.245, 0.52, 1.365)))]
        p = color_polynomial(beta_n)
        out["color"] = [math.exp(-math.sqrt(s) * p) for s in sigma]
    else:
        raise ValueError(f"unknown Principled Hair parametrization {parametrization!r}")
    out["beta_m"] = beta_m
    out["beta_n"] = beta_n
    out["alpha"] = _clamp(math.degrees(float(inputs.get("Offset", math.radians(2.0)))), -30.0, 30.0)
    out["eta"] = _clamp(inputs.get("IOR", 1.55), 1.0, 10.0)
    for key in ("Coat", "Random Color", "Random Roughness"):
        value = float(inputs.get(key, 0.0))
        if value > 1e-6:
            warnings.append(f"material {name}: {key} {value:g} is not mapped")
    return out, warnings


def surface(node_type: str, inputs: Mapping[str, Any], name: str = "material"):
    """The tress material for a surface shader node of ``node_type`` (``bl_idname``) with
    these input values, and warnings."""
    base = rgb(inputs.get("Base Color", inputs.get("Color", (0.8, 0.8, 0.8))))
    base = [_clamp(c, 0.0, 1.0) for c in base]
    if node_type == "ShaderNodeBsdfPrincipled":
        if float(inputs.get("Metallic", 0.0)) >= 0.999:
            return {"type": "mirror", "color": base}, [f"material {name}: metallic Principled BSDF as a mirror"]
        if float(inputs.get("Transmission Weight", inputs.get("Transmission", 0.0))) >= 0.999:
            ior = _clamp(inputs.get("IOR", 1.5), 1.0, 10.0)
            return {"type": "glass", "ior": ior, "color": base}, []
        warnings = []
        if float(inputs.get("Metallic", 0.0)) > 1e-6 or float(inputs.get("Coat Weight", 0.0)) > 1e-6:
            warnings.append(f"material {name}: Principled BSDF as diffuse; metallic and coat are not mapped")
        return {"type": "diffuse", "color": base}, warnings
    if node_type == "ShaderNodeBsdfDiffuse":
        return {"type": "diffuse", "color": base}, []
    if node_type in ("ShaderNodeBsdfGlossy", "ShaderNodeBsdfAnisotropic"):
        return {"type": "mirror", "color": base}, [f"material {name}: Glossy BSDF as a perfect mirror"]
    if node_type == "ShaderNodeBsdfGlass":
        return {"type": "glass", "ior": _clamp(inputs.get("IOR", 1.45), 1.0, 10.0), "color": base}, []
    if node_type == "ShaderNodeBsdfHair":
        return {"type": "tube", "diffuse": base}, []
    return {"type": "diffuse", "color": base}, [f"material {name}: {node_type} is not mapped; diffuse instead"]


def _input_values(node) -> dict[str, Any]:
    values = {}
    for socket in node.inputs:
        if hasattr(socket, "default_value"):
            v = socket.default_value
            values[socket.name] = tuple(v) if hasattr(v, "__len__") else v
    return values


def _uses_nodes(material) -> bool:
    """Blender 5 always shades with the node tree (``use_nodes`` is deprecated there)."""
    bpy = sys.modules.get("bpy")
    if bpy is not None and bpy.app.version >= (5, 0, 0):
        return True
    return bool(getattr(material, "use_nodes", False))


def _shader_node(material):
    """The shader node linked to the active Material Output's Surface, if any."""
    tree = material.node_tree if _uses_nodes(material) else None
    if tree is None:
        return None
    outputs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputMaterial"]
    active = [n for n in outputs if getattr(n, "is_active_output", False)] or outputs
    if not active:
        return None
    links = active[0].inputs["Surface"].links
    return links[0].from_node if links else None


def from_material(material, default: Mapping[str, Any], hair: bool = False):
    """The tress material for a Blender material (``None``: ``default``), and warnings."""
    if material is None:
        return dict(default), []
    node = _shader_node(material)
    name = material.name
    if node is None:
        color = [_clamp(c, 0.0, 1.0) for c in rgb(material.diffuse_color)]
        return ({"type": "tube", "diffuse": color} if hair else {"type": "diffuse", "color": color}), []
    return _from_node(node, name)


def _from_node(node, name: str):
    values = _input_values(node)
    warnings = [
        f"material {name}: the texture or node linked to {s.name} is not mapped; its own value is used"
        for s in node.inputs
        if s.is_linked
    ]
    if node.bl_idname == "ShaderNodeBsdfHairPrincipled":
        m, w = principled_hair(values, node.parametrization, getattr(node, "model", "CHIANG"), name)
    else:
        m, w = surface(node.bl_idname, values, name)
    return m, warnings + w
