using System;
using System.Collections.Generic;
using System.Linq;
using static GrCis.Rendering.Tests.Compatibility.GrCisApi;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>
/// GrCis's public library (the course repository's <c>common/</c> folder), written down as data: one
/// line per public type and per public or protected member (<c>Data/grcis-common-api.tsv</c>: file,
/// kind, type, member). Each must exist here with GrCis's name, or be covered by a line of
/// <c>Data/grcis-api-exceptions.tsv</c> that gives the reason. Exceptions marked <c>pending</c> are gaps
/// still to fill: such an entry must still be missing, so the list shrinks as the port grows.
/// </summary>
public class ApiSurfaceTests
{
  static List<Entry> Entries() => ApiLists.Read("grcis-common-api.tsv").Select(f => new Entry(f[0], f[1], f[2], f[3])).ToList();

  static List<GrCisApi.Exception> Exceptions() => GrCisApi.Exceptions("grcis-api-exceptions.tsv");

  [Fact]
  public void Every_public_member_of_GrCis_common_library_exists_or_has_a_documented_reason()
  {
    List<Entry> entries = Entries();
    List<GrCisApi.Exception> exceptions = Exceptions();
    Assert.True(entries.Count > 1000, "the API list looks truncated");

    (List<string> missing, List<string> stalePending) = ApiLists.Gaps(entries, GrCisApi.Exists,
      e => exceptions.FirstOrDefault(x => x.Covers(e)) is { } x ? (x.Scope, x.Reason) : null);
    Assert.True(missing.Count == 0, $"{missing.Count} GrCis members are missing:\n" + string.Join("\n", missing));
    Assert.True(stalePending.Count == 0, "pending exceptions that are no longer gaps:\n" + string.Join("\n", stalePending));
  }

  [Fact]
  public void Every_exception_covers_something()
  {
    List<Entry> entries = Entries();
    string[] unused = Exceptions().Where(x => !entries.Any(x.Covers)).Select(x => x.Scope).ToArray();
    Assert.True(unused.Length == 0, "exceptions that match no GrCis member: " + string.Join(", ", unused));
  }
}
