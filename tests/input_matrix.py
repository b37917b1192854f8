"""What the hostile-input matrices (test_hostile_inputs.py, test_scene_inputs.py,
test_untrusted_inputs.py) share: a folder's snapshot, to show a refused run wrote nothing, and the
smallest valid gmsh mesh of two bodies, to build bad meshes from."""
import os
import stat


def snapshot(folder):
    """Every entry under folder: a regular file's bytes, a link's ("link", target), any other
    entry's kind (stat.S_IFMT)."""
    result = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = os.path.join(root, name)
            info = os.lstat(path)
            key = os.path.relpath(path, folder)
            if stat.S_ISREG(info.st_mode):
                with open(path, "rb") as f:
                    result[key] = f.read()
            elif stat.S_ISLNK(info.st_mode):
                result[key] = ("link", os.readlink(path))
            else:
                result[key] = stat.S_IFMT(info.st_mode)
    return result


def two_quads_msh(z=0.0, first_node=None, crack=False, concave=False):
    """Two bodies of two quads each as a gmsh 4.1 mesh: a on y in [0, 1], b on [1, 2], the bondline
    y = 1, groups bottom, bond, top (curves) and a, b (surfaces). z for every node; node 1 at
    `first_node` (x, y, given as text) if set; with `crack`, b's last quad repeats a node; with
    `concave`, a's first quad is not convex."""
    nodes = [(x, y) for y in (0, 1, 2) for x in (0, 1, 2)]  # tags 1..9, a row per curve
    if concave:
        nodes[1] = (0.2, 0.8)
    text = [f"{x} {y} {z}" for x, y in nodes]
    if first_node:
        text[0] = f"{first_node[0]} {first_node[1]} {z}"
    last = "10 5 6 9 9" if crack else "10 5 6 9 8"
    return "\n".join([
        "$MeshFormat", "4.1 0 8", "$EndMeshFormat",
        "$PhysicalNames", "5", '1 1 "bottom"', '1 2 "bond"', '1 3 "top"', '2 4 "a"', '2 5 "b"', "$EndPhysicalNames",
        "$Entities", "0 3 2 0",
        "1 0 0 0 2 0 0 1 1 0", "2 0 1 0 2 1 0 1 2 0", "3 0 2 0 2 2 0 1 3 0",
        "1 0 0 0 2 1 0 1 4 0", "2 0 1 0 2 2 0 1 5 0", "$EndEntities",
        "$Nodes", "3 9 1 9",
        *[line for curve in range(3) for line in (f"1 {curve + 1} 0 3", *[str(3 * curve + k + 1) for k in range(3)],
                                                  *text[3 * curve:3 * curve + 3])],
        "$EndNodes",
        "$Elements", "5 10 1 10",
        "1 1 1 2", "1 1 2", "2 2 3",
        "1 2 1 2", "3 4 5", "4 5 6",
        "1 3 1 2", "5 7 8", "6 8 9",
        "2 1 3 2", "7 1 2 5 4", "8 2 3 6 5",
        "2 2 3 2", "9 4 5 8 7", last,
        "$EndElements", ""])
