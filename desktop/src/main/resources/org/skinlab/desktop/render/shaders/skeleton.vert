#version 330 core
// A joint of the skeleton overlay: its bind-space origin moved by its own skinning matrix, which
// gives the joint's posed place (the skinning matrix is world(joint) * inverse bind).

layout(location = 0) in vec3 aOrigin;
layout(location = 1) in uint aJoint;

uniform samplerBuffer uMatrices;
uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform int uColumns;
uniform float uSpacing;
uniform float uPointSize;

void main() {
    int o = int(aJoint) * 3;
    vec4 h = vec4(aOrigin, 1.0);
    vec3 p = vec3(dot(texelFetch(uMatrices, o), h), dot(texelFetch(uMatrices, o + 1), h),
            dot(texelFetch(uMatrices, o + 2), h));
    int column = gl_InstanceID % uColumns;
    int row = gl_InstanceID / uColumns;
    vec3 offset = vec3((float(column) - 0.5 * float(uColumns - 1)) * uSpacing, 0.0, -float(row) * uSpacing);
    gl_Position = uViewProjection * (uModel * vec4(p, 1.0) + vec4(offset, 0.0));
    gl_PointSize = uPointSize;
}
