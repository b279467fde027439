#version 300 es
in highp vec2 uv;
uniform highp float time;
out highp vec4 color;
precision highp float;
// origin: seeds/002_8b04b19c97ebb284.txt, "Introduction": the basic scene (no AO); the blog harness supplies uv, time and color
const vec3 lightPos = vec3(1.0, 3.0, 1.0);
const vec3 lightDir = normalize(lightPos);

float sol(vec3 p) {
    return p.y;
}

float ball(vec3 p, vec3 off) {
    p -= off;
    return length(p) - 0.5;
}

float wall(vec3 p) {
    float d = min(p.x + 2.0, p.z + 2.0);
    return d;
}

vec3 getWallColor(vec3 p) {
    p *= 2.0;
    vec3 baseColor = vec3(1.0);
    vec3 u = mod(floor(p), 2.0);
    return baseColor - vec3(abs(u.y - max(u.x, u.z))) * 0.095;
}

vec3 getFloorColor(vec3 p) {
    p *= 2.0;
    vec3 baseColor = vec3(1.0);
    vec3 u = mod(floor(p), 2.0);
    return baseColor - vec3(abs(u.x - u.z)) * 0.095;
}

vec2 map(vec3 p) {
    float closest = 1000.0;
    float id = -1.0;

    float dist = sol(p);
    if (dist < closest) { closest = dist; id = 0.5; }

    dist = ball(p, vec3(0.0, 0.1, 0.0));
    if (dist < closest) { closest = dist; id = 1.0; }

    dist = wall(p);
    if (dist < closest) { closest = dist; id = 2.0; }

    return vec2(closest, id);
}

vec2 intersect(vec3 ro, vec3 rd) {
    float depth = 0.0;
    float id = -1.0;
    
    for (int i = 0; i < 200; i++) {
        vec2 info = map(ro + rd * depth);
        if (info.x < 0.001) {
            id = info.y;
            break;
        }
        depth += info.x;
    }
    return vec2(depth, id);
}

vec3 getColor(float id, vec3 p) {
    if (id < -0.5) { return vec3(0.0); }
    if (id < 1.0) { return getFloorColor(p); }
    if (id < 2.0) { return vec3(0.4, 0.2, 0.1) * 2.0; }
    if (id < 3.0) { return getWallColor(p); }
    return vec3(1.0, 0.0, 0.0);
}

vec3 getNormal(vec3 p) {
    const float epsilon = 0.001;
    return normalize(vec3(
        map(p).x - map(vec3(p.x - epsilon, p.yz)).x,
        map(p).x - map(vec3(p.x, p.y - epsilon, p.z)).x,
        map(p).x - map(vec3(p.x, p.y, p.z - epsilon)).x
    ));
}

void main() {
    vec2 xy = uv * 2.0 - 1.0;
    vec3 ro = vec3(3.0 + sin(time) * 0.5, 3.0, 2.0 + sin(time * 0.2) * 0.5);
    vec3 center = vec3(0.0, 0.0, 0.0);
    
    vec3 front = normalize(center - ro);
    vec3 right = normalize(cross(front, vec3(0.0, 1.0, 0.0)));
    vec3 up = normalize(cross(right, front));
    mat4 lookAt = mat4(
        vec4(right, 0.0),
        vec4(up, 0.0),
        vec4(front, 0.0),
        vec4(0.0, 0.0, 0.0, 1.0)
    );
    vec3 rd = normalize(vec3(lookAt * vec4(xy, 2.0, 1.0)));
    vec2 info = intersect(ro, rd);
    vec3 pos = ro + rd * info.x;
    vec3 n = getNormal(pos);

    float ambient = 1.0;
    float diffuse = max(dot(n, lightDir), 0.0);
    float back = max(dot(n, vec3(-lightDir.x, 0.0, -lightDir.z)), 0.0);
    float dome = 0.2 + 0.8 * clamp(rd.y, 0.0, 1.0);
    float sol = 0.2 + 0.8 * clamp(-rd.y, 0.0, 1.0);
    
    vec3 light = vec3(0.0);
    light += ambient * vec3(0.1, 0.1, 0.2);
    light += diffuse * vec3(0.65, 0.6, 0.4);
    light += back * vec3(0.3, 0.2, 0.1);
    light += dome * vec3(0.5, 0.5, 0.7);
    light += sol * vec3(0.3, 0.3, 0.32);
    
    vec3 objColor = getColor(info.y, pos) * light;
    objColor = pow(objColor, vec3(0.4545));
    color = vec4(objColor, 1.0);
}
