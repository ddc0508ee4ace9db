using System.Globalization;
using System.Text;

namespace Support;

/// <summary>GrCis's text helpers.</summary>
public class TextUtils
{
  /// <summary>The text without accents (é → e, ř → r): decomposed, non-spacing marks dropped, recomposed.</summary>
  public static string RemoveDiacritics(string str)
  {
    var sb = new StringBuilder(str.Length);
    foreach (char c in str.Normalize(NormalizationForm.FormD))
      if (CharUnicodeInfo.GetUnicodeCategory(c) != UnicodeCategory.NonSpacingMark)
        sb.Append(c);
    return sb.ToString().Normalize(NormalizationForm.FormC);
  }
}
