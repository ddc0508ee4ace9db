using OpenTK;
using System.Linq;

// OpenTK 3 scripts import 'OpenTK'; the vector types come from the default imports.
Vector3d a = new Vector3d(1.0, 2.0, 3.0);
Matrix4d m = Matrix4d.CreateTranslation(1.0, 0.0, 0.0);
Vector3d b = Vector3d.TransformPosition(a, m);
context["sum"] = new[] { b.X, b.Y, b.Z }.Sum();
