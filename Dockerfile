# The grcis image of docs/scale-out.md: a framework-dependent publish on the ASP.NET Core runtime
# image, which holds both shared runtimes grcis needs (Microsoft.NETCore.App and, for the studio in
# the same executable, Microsoft.AspNetCore.App). Build from the repository root:
#   docker build -t registry.example.org/grcis:1 .
FROM mcr.microsoft.com/dotnet/sdk:10.0 AS build
WORKDIR /src
COPY . .
RUN dotnet publish src/GrCis.Cli -c Release -o /opt/grcis

FROM mcr.microsoft.com/dotnet/aspnet:10.0
RUN apt-get update && apt-get install -y --no-install-recommends ffmpeg && rm -rf /var/lib/apt/lists/*
COPY --from=build /opt/grcis /opt/grcis
ENTRYPOINT ["/opt/grcis/grcis"]
