using System.Text;

namespace GrCis.Hosting;

/// <summary>File-name-safe form of a scene name: "Sphere on the plane" → "sphere-on-the-plane".</summary>
public static class Slug
{
  public static string Of(string name)
  {
    var sb = new StringBuilder(name.Length);
    bool dash = false;
    foreach (char c in name)
    {
      if (char.IsAsciiLetterOrDigit(c))
      {
        if (dash && sb.Length > 0)
          sb.Append('-');
        sb.Append(char.ToLowerInvariant(c));
        dash = false;
      }
      else
        dash = true;
    }
    return sb.Length > 0 ? sb.ToString() : "render";
  }
}
