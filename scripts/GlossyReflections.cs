//////////////////////////////////////////////////
// Glossy reflections (distributed ray tracing): five metallic balls on a mirror-like checkered
// floor, their Phong exponent H growing from left to right. DistributedRayTracing samples each
// reflected ray from the cos^H lobe around the mirror direction, so a low H blurs the reflection
// and a high H keeps it sharp. Needs supersampling (16 samples per pixel by default).

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "glossy reflections: Phong exponents 8 .. 2048 from left to right";
context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();
context[PropertyName.CTX_SUPERSAMPLING] = 16;

CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.9, 0.9, 0.9 }, 0.1, 0.5, 0.5, 64));
scene.Intersectable = root;
scene.BackgroundColor = new double[] { 0.1, 0.15, 0.25 };
scene.Camera = new StaticCamera(new Vector3d(0.0, 1.6, -7.0), new Vector3d(0.0, -0.25, 1.0), 50.0);
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.6));
scene.Sources.Add(new PointLightSource(new Vector3d(-4.0, 6.0, -5.0), 1.0));

int[] exponents = { 8, 32, 128, 512, 2048 };
for (int k = 0; k < exponents.Length; k++)
{
  Sphere ball = new Sphere();
  ball.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.9, 0.6, 0.2 }, 0.1, 0.2, 0.8, exponents[k]));
  root.InsertChild(ball, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(-3.0 + 1.5 * k, -0.4, 0.0));
}

// A glossy checkered floor (H 64) reflects the balls, blurred.
Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.2, 0.2, 0.25 });
floor.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(1.0, 1.0, new double[] { 0.8, 0.8, 0.8 }));
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
