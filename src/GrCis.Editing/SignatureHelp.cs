using System.Collections.Generic;

namespace GrCis.Editing;

/// <summary>The overloads of the call or <c>new</c> the caret is in, with the one and the argument it is at.</summary>
/// <param name="Signatures">Accessible overloads (constructors of the created type, or the invoked method group).</param>
/// <param name="Active">Index of the overload that fits the arguments typed so far (the bound one when it binds).</param>
/// <param name="ActiveParameter">Index of the argument the caret is in (commas before it at the call's own level).</param>
public sealed record SignatureHelp(IReadOnlyList<SignatureEntry> Signatures, int Active, int ActiveParameter);
