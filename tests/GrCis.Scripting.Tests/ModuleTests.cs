using System.IO;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Scripting.Tests;

/// <summary>A folder of ordinary .cs files becomes an assembly scripts can use.</summary>
public class ModuleTests
{
  [Fact]
  public void Module_solid_and_texture_are_usable_from_a_script()
  {
    using var host = new ScriptHost();
    ScriptModule module = host.AddModule(TestData.Module("SomeAuthor"));
    Assert.Equal(2, module.Files.Count);
    Assert.Contains(module.Files, f => f.EndsWith(Path.Combine("Textures", "RingsTexture.cs")));

    ScriptScene result = host.Load(TestData.Script("ModuleUser.cs"));
    var root = Assert.IsType<CSGInnerNode>(result.Scene.Intersectable);
    ISceneNode slab = Assert.Single(root.Children);
    Assert.Equal("SomeAuthor.Slab", slab.GetType().FullName);
    Assert.IsAssignableFrom<ISolid>(slab);
    Assert.Same(module.Assembly, slab.GetType().Assembly);

    // The module's solid really intersects: slab of thickness 0.5 around local z = 0.
    var hits = slab.Intersect(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1))!.ToList();
    Assert.Equal(2, hits.Count);
    Assert.Equal(4.75, hits[0].T, 12);
    Assert.True(hits[0].Enter);
    Assert.Equal(5.25, hits[1].T, 12);

    // And its texture: ring index 3 (odd) at r = 1.6 with frequency 2 gets Color2.
    var texture = (ITexture)slab.GetAttribute(PropertyName.TEXTURE)!;
    var inter = new Intersection { CoordLocal = new Vector3d(1.6, 0, 0), SurfaceColor = new[] { 0.0, 0.0, 0.0 } };
    Assert.Equal(3L, texture.Apply(inter));
    Assert.Equal(new[] { 1.0, 1.0, 1.0 }, inter.SurfaceColor);
  }

  [Fact]
  public void Script_using_a_module_fails_to_compile_without_it()
  {
    using var host = new ScriptHost();
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(TestData.Script("ModuleUser.cs")));
    Assert.Contains(ex.Errors, d => d.Id == "CS0246" && d.Line == 1 && d.Column == 7);
  }

  [Fact]
  public void Adding_the_same_module_twice_compiles_it_once()
  {
    using var host = new ScriptHost();
    ScriptModule a = host.AddModule(TestData.Module("SomeAuthor"));
    ScriptModule b = host.AddModule(TestData.Module("SomeAuthor"));
    Assert.Same(a, b);
    Assert.Equal(1, host.ModuleCompilationCount);
    Assert.Single(host.Modules);
  }

  [Fact]
  public void Module_compile_errors_name_the_module_file_line_and_column()
  {
    using var host = new ScriptHost();
    string file = Path.GetFullPath(Path.Combine(TestData.Module("Broken"), "Oops.cs"));
    var ex = Assert.Throws<ScriptCompilationException>(() => host.AddModule(TestData.Module("Broken")));
    ScriptDiagnostic error = Assert.Single(ex.Errors);
    Assert.Equal($"{file}(5,25): error CS0103: The name 'missing' does not exist in the current context", error.ToString());
    Assert.Empty(host.Modules);
  }

  [Fact]
  public void Missing_module_folder_is_a_clear_error()
  {
    using var host = new ScriptHost();
    string dir = Path.Combine(TestData.Root, "modules", "NoSuchAuthor");
    var ex = Assert.Throws<DirectoryNotFoundException>(() => host.AddModule(dir));
    Assert.Equal($"Module folder not found: '{Path.GetFullPath(dir)}'", ex.Message);
  }

  [Fact]
  public void Adding_a_module_changes_the_cache_key_of_scripts()
  {
    using var host = new ScriptHost();
    string path = TestData.Script("TimeDependent.cs");
    host.Compile(path);
    host.AddModule(TestData.Module("SomeAuthor"));
    host.Compile(path);
    Assert.Equal(2, host.CompilationCount);
  }
}
