"""rtpro's material models as Cycles shader nodes, shared by render_gltf.py and
render_environment.py: Lambert is Cycles' Diffuse BSDF at roughness 0, a conductor its Glossy BSDF
with multiple-scattering GGX (alpha = roughness^2 in both), clear glass its sharp Glass BSDF."""


def empty_node_tree(material):
    """Gives `material` shader nodes holding only an output node: (nodes, links, output)."""
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    return nodes, links, nodes.new("ShaderNodeOutputMaterial")


def bsdf_node(nodes, kind, color, roughness=0.0, ior=1.5):
    """A new BSDF node in `nodes` for `kind`: "lambert", "metal" (at `roughness`) or "glass" (at
    `ior`), of RGB `color`."""
    if kind == "lambert":
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Roughness"].default_value = 0.0
    elif kind == "metal":
        bsdf = nodes.new("ShaderNodeBsdfGlossy")
        bsdf.distribution = "MULTI_GGX"
        bsdf.inputs["Roughness"].default_value = roughness
    elif kind == "glass":
        bsdf = nodes.new("ShaderNodeBsdfGlass")
        bsdf.distribution = "SHARP"
        bsdf.inputs["IOR"].default_value = ior
    else:
        raise ValueError("no Cycles node for material kind %r" % kind)
    bsdf.inputs["Color"].default_value = (color[0], color[1], color[2], 1.0)
    return bsdf
