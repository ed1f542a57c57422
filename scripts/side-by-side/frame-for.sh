# Sourced by side-by-side.sh and separate-jvms.sh (which set $src): frame_for JAR DIR compiles
# Frame.java against JAR into DIR. Frame.java imports the frame's values from dev.trisect.render;
# builds before commit 1c5f986 had them in pipeline, tessellate and raster, so for such a jar a copy
# with those imports is compiled.
frame_for() {
  local jar=$1 dir=$2
  mkdir -p "$dir/src"
  if unzip -l "$jar" 'dev/trisect/render/RenderSettings.class' >/dev/null 2>&1; then
    cp "$src/Frame.java" "$dir/src/Frame.java"
  else
    sed -e 's/dev\.trisect\.render\.\(RenderSettings\|RenderMode\|CullMode\|FrameStats\);/dev.trisect.pipeline.\1;/' \
        -e 's/dev\.trisect\.render\.\(TessellationSettings\|SplitPolicy\|SplitPoint\);/dev.trisect.tessellate.\1;/' \
        -e 's/dev\.trisect\.render\.\(Framebuffer\|BorderStyle\);/dev.trisect.raster.\1;/' \
        "$src/Frame.java" >"$dir/src/Frame.java"
  fi
  javac -d "$dir" -cp "$jar" "$dir/src/Frame.java"
}
