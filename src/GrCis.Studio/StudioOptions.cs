using System.Collections.Generic;

namespace GrCis.Studio;

/// <summary>How <c>grcis studio</c> was started: where it listens, its token, and the scripts and folders it may read.</summary>
public sealed record StudioOptions
{
  /// <summary>Address to bind; loopback by default, so only this machine (or an <c>ssh -L</c> tunnel) reaches it.</summary>
  public string Host { get; init; } = "127.0.0.1";

  /// <summary>Port; 0 = a free one.</summary>
  public int Port { get; init; }

  /// <summary>The token every request must carry; null = a new random one.</summary>
  public string? Token { get; init; }

  /// <summary>Scene scripts and folders given on the command line: the only files the studio reads or writes.</summary>
  public IReadOnlyList<string> Paths { get; init; } = [];

  /// <summary>Leave the built-in scenes out of the scene list (GrCis's <c>-nodefault</c>).</summary>
  public bool NoDefault { get; init; }

  /// <summary>
  /// Load the editor's language services in the background as the studio starts, so the page's first completion is
  /// answered at once (<c>grcis studio</c> does; an embedding that never edits leaves it off and saves the seconds).
  /// </summary>
  public bool WarmEditor { get; init; }

  /// <summary>Where compiled scene scripts are kept between runs (null: compiled afresh in each studio).</summary>
  public GrCis.Scripting.Caching.ScriptCache? ScriptCache { get; init; }

  /// <summary>
  /// The port the user reaches the studio on when a <see cref="StudioSupervisor"/> forwards to this studio (0: none does,
  /// it is <see cref="Port"/>). Such a studio listens on 127.0.0.1 whatever <see cref="Host"/> says, and its access rules
  /// (the Host and Origin it accepts, the token's cookie) are those of <see cref="Host"/> and this port: the supervisor
  /// passes the user's Host and Origin on unchanged.
  /// </summary>
  public int PublicPort { get; init; }

  /// <summary>What the page says first (the supervisor's sentence on why it restarted this studio); null = nothing.</summary>
  public string? Notice { get; init; }

  /// <summary>How many studios the supervisor started before this one (0 = the first): a page that sees it change starts afresh.</summary>
  public int Generation { get; init; }

  /// <summary>True when <see cref="Host"/> is a loopback address (or <c>localhost</c>).</summary>
  public bool IsLoopback => Host is "127.0.0.1" or "localhost" or "::1" or "[::1]";

  /// <summary>True when <see cref="Host"/> means every interface (0.0.0.0 or ::).</summary>
  public bool IsAnyAddress => Host is "0.0.0.0" or "::" or "[::]";

  /// <summary>How the address is written in a URL or Host header: an IPv6 address in brackets.</summary>
  public static string UrlHost(string host) => host.Contains(':') && !host.StartsWith('[') ? $"[{host}]" : host;
}
