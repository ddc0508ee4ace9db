# Imports glTF files into Blender with its own glTF importer and prints one line, "GRCIS-RESULT <json>": per file the
# objects Blender made of it (meshes, cameras, lights). Used by BlenderImportTests.
#   blender -b --factory-startup --python import-gltf.py -- <file.glb>...
import json
import os
import sys

import bpy
import numpy

# Debian pairs Blender 3.4 with numpy 1.24, which dropped the alias numpy.bool that Blender 3.4's importer still uses.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

reports = []
for path in sys.argv[sys.argv.index("--") + 1:]:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=path)
    kinds = [o.type for o in bpy.context.scene.objects]
    reports.append({"file": os.path.basename(path), "meshes": kinds.count("MESH"), "cameras": kinds.count("CAMERA"),
                    "lights": kinds.count("LIGHT")})
print("GRCIS-RESULT " + json.dumps(reports))
