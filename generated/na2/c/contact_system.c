/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_system() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 1ffd02983b32fea1953b31d6b4da6e985de5a598f8e69763f0a5d6374958d5e8
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na2_contact_system_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
#define casadi_s8 CASADI_PREFIX(s8)
#define casadi_s9 CASADI_PREFIX(s9)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {5, 1, 1};
static const casadi_int casadi_s1[3] = {2, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {25, 1, 1};
static const casadi_int casadi_s4[3] = {1, 1, 1};
static const casadi_int casadi_s5[3] = {5, 5, 1};
static const casadi_int casadi_s6[3] = {4, 4, 1};
static const casadi_int casadi_s7[3] = {4, 1, 1};
static const casadi_int casadi_s8[3] = {5, 4, 1};
static const casadi_int casadi_s9[3] = {3, 4, 1};

/* snakecg_na2_contact_system:(q[5],v[5],tau[2],q_obj[3],v_obj[3],f_obj[3],K[25],contact_link[3],side,object_mass,object_inertia,rho[2],wheel_offset[3],contact_offset,object_distance,placed)->(M[5x5],delassus[4x4],b[4],qdd_free[5],a_obj_free[3],qdd_from_lam[5x4],a_obj_from_lam[3x4],gap,s) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103, a104, a105, a106, a107;
  casadi_real a108, a109, a110, a111, a112, a113, a114, a115, a116, a117;
  a000=arg[6]? arg[6][12] : 0;
  if (res[0]!=0) res[0][0]=a000;
  a001=0.;
  if (res[0]!=0) res[0][1]=a001;
  a002=arg[6]? arg[6][15] : 0;
  a003=arg[0]? arg[0][2] : 0;
  a004=cos(a003);
  a005=arg[0]? arg[0][3] : 0;
  a006=cos(a005);
  a007=(a004*a006);
  a003=sin(a003);
  a005=sin(a005);
  a008=(a003*a005);
  a007=(a007-a008);
  a008=arg[0]? arg[0][4] : 0;
  a009=sin(a008);
  a010=(a007*a009);
  a008=cos(a008);
  a005=(a004*a005);
  a011=(a006*a003);
  a011=(a005+a011);
  a012=(a008*a011);
  a012=(a010+a012);
  a013=(a002*a012);
  a014=arg[6]? arg[6][14] : 0;
  a015=(a014*a011);
  a015=(a013+a015);
  a016=arg[6]? arg[6][13] : 0;
  a017=(a016*a003);
  a017=(a015+a017);
  a018=(-a017);
  if (res[0]!=0) res[0][2]=a018;
  a019=(-a015);
  if (res[0]!=0) res[0][3]=a019;
  a020=(-a013);
  if (res[0]!=0) res[0][4]=a020;
  if (res[0]!=0) res[0][5]=a001;
  if (res[0]!=0) res[0][6]=a000;
  a021=(a007*a008);
  a022=(a011*a009);
  a022=(a021-a022);
  a002=(a002*a022);
  a014=(a014*a007);
  a014=(a002+a014);
  a016=(a016*a004);
  a016=(a014+a016);
  if (res[0]!=0) res[0][7]=a016;
  if (res[0]!=0) res[0][8]=a014;
  if (res[0]!=0) res[0][9]=a002;
  if (res[0]!=0) res[0][10]=a018;
  if (res[0]!=0) res[0][11]=a016;
  a018=arg[6]? arg[6][4] : 0;
  a023=(a007*a018);
  a023=(a002*a023);
  a024=(a011*a018);
  a024=(a013*a024);
  a023=(a023+a024);
  a024=arg[6]? arg[6][24] : 0;
  a025=(a023+a024);
  a023=(a025+a023);
  a026=arg[6]? arg[6][23] : 0;
  a023=(a023+a026);
  a026=arg[6]? arg[6][3] : 0;
  a027=arg[6]? arg[6][9] : 0;
  a026=(a026-a027);
  a028=(a004*a026);
  a029=(a014*a028);
  a030=(a026*a003);
  a031=(a015*a030);
  a029=(a029+a031);
  a031=(a023+a029);
  a029=(a031+a029);
  a032=arg[6]? arg[6][22] : 0;
  a029=(a029+a032);
  if (res[0]!=0) res[0][12]=a029;
  if (res[0]!=0) res[0][13]=a031;
  a032=(a002*a028);
  a033=(a013*a030);
  a032=(a032+a033);
  a032=(a025+a032);
  if (res[0]!=0) res[0][14]=a032;
  if (res[0]!=0) res[0][15]=a019;
  if (res[0]!=0) res[0][16]=a014;
  if (res[0]!=0) res[0][17]=a031;
  if (res[0]!=0) res[0][18]=a023;
  if (res[0]!=0) res[0][19]=a025;
  if (res[0]!=0) res[0][20]=a020;
  if (res[0]!=0) res[0][21]=a002;
  if (res[0]!=0) res[0][22]=a032;
  if (res[0]!=0) res[0][23]=a025;
  if (res[0]!=0) res[0][24]=a024;
  a020=arg[7]? arg[7][0] : 0;
  a019=(a020*a003);
  a033=arg[7]? arg[7][1] : 0;
  a006=(a003*a006);
  a006=(a006+a005);
  a005=(a033*a006);
  a019=(a019+a005);
  a005=arg[7]? arg[7][2] : 0;
  a008=(a006*a008);
  a008=(a008+a010);
  a010=(a005*a008);
  a019=(a019+a010);
  a010=arg[8]? arg[8][0] : 0;
  a034=(a019*a010);
  a035=(a020+a033);
  a035=(a035+a005);
  a036=(a034*a035);
  a037=(a036/a000);
  a017=(a017/a000);
  a038=arg[0]? arg[0][1] : 0;
  a039=(a038+a030);
  a040=arg[6]? arg[6][10] : 0;
  a041=(a011*a040);
  a042=(a039+a041);
  a043=(a038-a042);
  a044=(a033*a043);
  a018=(a018-a040);
  a045=(a018*a011);
  a046=(a042+a045);
  a047=arg[6]? arg[6][11] : 0;
  a048=(a012*a047);
  a046=(a046+a048);
  a049=(a038-a046);
  a050=(a005*a049);
  a044=(a044+a050);
  a050=(a034*a044);
  a051=(a020*a004);
  a052=(a033*a007);
  a051=(a051+a052);
  a009=(a006*a009);
  a021=(a021-a009);
  a009=(a005*a021);
  a051=(a051+a009);
  a009=(a051*a010);
  a052=arg[0]? arg[0][0] : 0;
  a053=(a052+a028);
  a054=(a007*a040);
  a055=(a053+a054);
  a056=(a055-a052);
  a057=(a033*a056);
  a058=(a007*a018);
  a059=(a055+a058);
  a060=(a022*a047);
  a059=(a059+a060);
  a061=(a059-a052);
  a062=(a005*a061);
  a057=(a057+a062);
  a062=(a009*a057);
  a050=(a050-a062);
  a027=(a027*a020);
  a062=(a040*a033);
  a027=(a027+a062);
  a062=(a047*a005);
  a027=(a027+a062);
  a062=(a010*a027);
  a063=casadi_sq(a019);
  a063=(a062*a063);
  a064=casadi_sq(a051);
  a062=(a062*a064);
  a063=(a063+a062);
  a062=1.;
  a064=arg[15]? arg[15][0] : 0;
  a062=(a062-a064);
  a065=arg[3]? arg[3][2] : 0;
  a066=cos(a065);
  a066=(a062*a066);
  a067=(a064*a051);
  a066=(a066+a067);
  a067=arg[11]? arg[11][1] : 0;
  a067=(a062*a067);
  a068=arg[14]? arg[14][0] : 0;
  a069=(a010*a068);
  a069=(a064*a069);
  a067=(a067-a069);
  a069=(a066*a067);
  a065=sin(a065);
  a065=(a062*a065);
  a070=(a064*a019);
  a065=(a065+a070);
  a070=arg[11]? arg[11][0] : 0;
  a070=(a062*a070);
  a071=(a065*a070);
  a069=(a069+a071);
  a071=arg[3]? arg[3][1] : 0;
  a071=(a062*a071);
  a072=(a038*a020);
  a042=(a042*a033);
  a072=(a072+a042);
  a042=(a046*a005);
  a072=(a072+a042);
  a042=arg[13]? arg[13][0] : 0;
  a042=(a042-a027);
  a073=(a042*a019);
  a073=(a072+a073);
  a074=(a010*a051);
  a074=(a068*a074);
  a073=(a073+a074);
  a073=(a064*a073);
  a071=(a071+a073);
  a071=(a069+a071);
  a073=(a019*a027);
  a071=(a071+a073);
  a071=(a071-a072);
  a072=(a034*a071);
  a063=(a063-a072);
  a066=(a066*a070);
  a065=(a065*a067);
  a066=(a066-a065);
  a065=arg[3]? arg[3][0] : 0;
  a062=(a062*a065);
  a020=(a052*a020);
  a055=(a055*a033);
  a020=(a020+a055);
  a055=(a059*a005);
  a020=(a020+a055);
  a042=(a042*a051);
  a042=(a020+a042);
  a055=(a010*a019);
  a068=(a068*a055);
  a042=(a042-a068);
  a064=(a064*a042);
  a062=(a062+a064);
  a062=(a066+a062);
  a027=(a051*a027);
  a062=(a062+a027);
  a062=(a062-a020);
  a020=(a009*a062);
  a063=(a063-a020);
  a020=(a063*a035);
  a050=(a050+a020);
  a020=(a017*a036);
  a020=(a050+a020);
  a016=(a016/a000);
  a027=(a009*a035);
  a064=(a016*a027);
  a020=(a020+a064);
  a064=casadi_sq(a017);
  a064=(a064*a000);
  a029=(a029-a064);
  a064=casadi_sq(a016);
  a064=(a064*a000);
  a029=(a029-a064);
  a064=(a020/a029);
  a015=(a015/a000);
  a042=(a015*a017);
  a042=(a042*a000);
  a031=(a031-a042);
  a014=(a014/a000);
  a042=(a014*a016);
  a042=(a042*a000);
  a031=(a031-a042);
  a031=(a031/a029);
  a039=(a039-a046);
  a046=(a005*a039);
  a042=(a033*a041);
  a046=(a046-a042);
  a042=(a034*a046);
  a068=(a033*a054);
  a059=(a059-a053);
  a053=(a005*a059);
  a068=(a068+a053);
  a053=(a009*a068);
  a042=(a042-a053);
  a053=(a033+a005);
  a055=(a063*a053);
  a042=(a042+a055);
  a055=(a015*a036);
  a055=(a042+a055);
  a065=(a014*a027);
  a055=(a055+a065);
  a065=(a031*a020);
  a055=(a055-a065);
  a065=casadi_sq(a015);
  a065=(a065*a000);
  a023=(a023-a065);
  a065=casadi_sq(a014);
  a065=(a065*a000);
  a023=(a023-a065);
  a065=casadi_sq(a031);
  a065=(a065*a029);
  a023=(a023-a065);
  a065=(a055/a023);
  a013=(a013/a000);
  a067=(a013*a015);
  a067=(a067*a000);
  a025=(a025-a067);
  a002=(a002/a000);
  a067=(a002*a014);
  a067=(a067*a000);
  a025=(a025-a067);
  a067=(a013*a017);
  a067=(a067*a000);
  a032=(a032-a067);
  a067=(a002*a016);
  a067=(a067*a000);
  a032=(a032-a067);
  a032=(a032/a029);
  a067=(a032*a031);
  a067=(a067*a029);
  a025=(a025-a067);
  a025=(a025/a023);
  a063=(a063*a005);
  a067=(a005*a048);
  a070=(a034*a067);
  a072=(a005*a060);
  a073=(a009*a072);
  a070=(a070+a073);
  a063=(a063-a070);
  a070=(a013*a036);
  a070=(a063+a070);
  a073=(a002*a027);
  a070=(a070+a073);
  a020=(a032*a020);
  a070=(a070-a020);
  a055=(a025*a055);
  a070=(a070-a055);
  a055=casadi_sq(a013);
  a055=(a055*a000);
  a024=(a024-a055);
  a055=casadi_sq(a002);
  a055=(a055*a000);
  a024=(a024-a055);
  a055=casadi_sq(a032);
  a055=(a055*a029);
  a024=(a024-a055);
  a055=casadi_sq(a025);
  a055=(a055*a023);
  a024=(a024-a055);
  a070=(a070/a024);
  a055=(a025*a070);
  a065=(a065-a055);
  a055=(a031*a065);
  a064=(a064-a055);
  a055=(a032*a070);
  a064=(a064-a055);
  a055=(a017*a064);
  a037=(a037+a055);
  a055=(a015*a065);
  a037=(a037+a055);
  a055=(a013*a070);
  a037=(a037+a055);
  a055=(a036*a037);
  a020=(a027/a000);
  a073=(a016*a064);
  a020=(a020+a073);
  a073=(a014*a065);
  a020=(a020+a073);
  a073=(a002*a070);
  a020=(a020+a073);
  a073=(a027*a020);
  a055=(a055+a073);
  a073=(a050*a064);
  a055=(a055+a073);
  a073=(a042*a065);
  a055=(a055+a073);
  a073=(a063*a070);
  a055=(a055+a073);
  a073=arg[9]? arg[9][0] : 0;
  a074=(a034/a073);
  a075=(a034*a074);
  a076=(a009/a073);
  a077=(a009*a076);
  a075=(a075+a077);
  a077=(a051*a066);
  a077=(a077*a010);
  a078=(a034*a069);
  a077=(a077+a078);
  a078=arg[10]? arg[10][0] : 0;
  a079=(a077/a078);
  a080=(a077*a079);
  a075=(a075+a080);
  a055=(a055+a075);
  if (res[1]!=0) res[1][0]=a055;
  a055=arg[12]? arg[12][0] : 0;
  a075=(a055*a064);
  a080=(a003*a037);
  a081=(a004*a020);
  a080=(a080+a081);
  a075=(a075-a080);
  if (res[1]!=0) res[1][1]=a075;
  a075=(a007*a056);
  a080=(a006*a043);
  a075=(a075-a080);
  a080=arg[12]? arg[12][1] : 0;
  a075=(a075+a080);
  a081=(a075*a064);
  a082=(a006*a037);
  a083=(a007*a020);
  a082=(a082+a083);
  a081=(a081-a082);
  a082=(a006*a041);
  a083=(a007*a054);
  a082=(a082+a083);
  a082=(a082+a080);
  a080=(a082*a065);
  a081=(a081+a080);
  if (res[1]!=0) res[1][2]=a081;
  a081=(a021*a061);
  a080=(a008*a049);
  a081=(a081-a080);
  a080=arg[12]? arg[12][2] : 0;
  a081=(a081+a080);
  a083=(a081*a064);
  a084=(a008*a037);
  a085=(a021*a020);
  a084=(a084+a085);
  a083=(a083-a084);
  a084=(a021*a059);
  a085=(a008*a039);
  a084=(a084-a085);
  a084=(a084+a080);
  a085=(a084*a065);
  a083=(a083+a085);
  a085=(a008*a048);
  a086=(a021*a060);
  a085=(a085+a086);
  a085=(a085+a080);
  a080=(a085*a070);
  a083=(a083+a080);
  if (res[1]!=0) res[1][3]=a083;
  a083=(a017*a003);
  a083=(a055-a083);
  a080=(a016*a004);
  a083=(a083-a080);
  a080=(a083/a029);
  a086=(a015*a003);
  a087=(a014*a004);
  a086=(a086+a087);
  a087=(a031*a083);
  a086=(a086+a087);
  a087=(a086/a023);
  a086=(a025*a086);
  a088=(a013*a003);
  a089=(a002*a004);
  a088=(a088+a089);
  a083=(a032*a083);
  a088=(a088+a083);
  a086=(a086-a088);
  a086=(a086/a024);
  a088=(a025*a086);
  a087=(a087+a088);
  a088=(a031*a087);
  a080=(a080+a088);
  a088=(a032*a086);
  a080=(a080-a088);
  a088=(a017*a080);
  a083=(a003/a000);
  a088=(a088-a083);
  a083=(a015*a087);
  a088=(a088-a083);
  a083=(a013*a086);
  a088=(a088+a083);
  a083=(a036*a088);
  a089=(a004/a000);
  a090=(a016*a080);
  a089=(a089-a090);
  a090=(a014*a087);
  a089=(a089+a090);
  a090=(a002*a086);
  a089=(a089-a090);
  a090=(a027*a089);
  a083=(a083-a090);
  a090=(a050*a080);
  a083=(a083+a090);
  a090=(a042*a087);
  a083=(a083-a090);
  a090=(a063*a086);
  a083=(a083+a090);
  if (res[1]!=0) res[1][4]=a083;
  a083=(a004*a089);
  a090=(a003*a088);
  a083=(a083-a090);
  a090=(a055*a080);
  a083=(a083+a090);
  if (res[1]!=0) res[1][5]=a083;
  a083=(a007*a089);
  a090=(a006*a088);
  a083=(a083-a090);
  a090=(a075*a080);
  a083=(a083+a090);
  a090=(a082*a087);
  a083=(a083-a090);
  if (res[1]!=0) res[1][6]=a083;
  a083=(a021*a089);
  a090=(a008*a088);
  a083=(a083-a090);
  a090=(a081*a080);
  a083=(a083+a090);
  a090=(a084*a087);
  a083=(a083-a090);
  a090=(a085*a086);
  a083=(a083+a090);
  if (res[1]!=0) res[1][7]=a083;
  a083=(a017*a006);
  a083=(a075-a083);
  a090=(a016*a007);
  a083=(a083-a090);
  a090=(a083/a029);
  a091=(a015*a006);
  a091=(a082-a091);
  a092=(a014*a007);
  a091=(a091-a092);
  a092=(a031*a083);
  a091=(a091-a092);
  a092=(a091/a023);
  a093=(a013*a006);
  a094=(a002*a007);
  a093=(a093+a094);
  a083=(a032*a083);
  a093=(a093+a083);
  a091=(a025*a091);
  a093=(a093+a091);
  a093=(a093/a024);
  a091=(a025*a093);
  a092=(a092+a091);
  a091=(a031*a092);
  a090=(a090-a091);
  a091=(a032*a093);
  a090=(a090+a091);
  a091=(a017*a090);
  a083=(a006/a000);
  a091=(a091-a083);
  a083=(a015*a092);
  a091=(a091+a083);
  a083=(a013*a093);
  a091=(a091-a083);
  a083=(a036*a091);
  a094=(a007/a000);
  a095=(a016*a090);
  a094=(a094-a095);
  a095=(a014*a092);
  a094=(a094-a095);
  a095=(a002*a093);
  a094=(a094+a095);
  a095=(a027*a094);
  a083=(a083-a095);
  a095=(a050*a090);
  a083=(a083+a095);
  a095=(a042*a092);
  a083=(a083+a095);
  a095=(a063*a093);
  a083=(a083-a095);
  if (res[1]!=0) res[1][8]=a083;
  a083=(a004*a094);
  a095=(a003*a091);
  a083=(a083-a095);
  a095=(a055*a090);
  a083=(a083+a095);
  if (res[1]!=0) res[1][9]=a083;
  a083=(a007*a094);
  a095=(a006*a091);
  a083=(a083-a095);
  a095=(a075*a090);
  a083=(a083+a095);
  a095=(a082*a092);
  a083=(a083+a095);
  if (res[1]!=0) res[1][10]=a083;
  a083=(a021*a094);
  a095=(a008*a091);
  a083=(a083-a095);
  a095=(a081*a090);
  a083=(a083+a095);
  a095=(a084*a092);
  a083=(a083+a095);
  a095=(a085*a093);
  a083=(a083-a095);
  if (res[1]!=0) res[1][11]=a083;
  a083=(a017*a008);
  a083=(a081-a083);
  a095=(a016*a021);
  a083=(a083-a095);
  a095=(a083/a029);
  a096=(a015*a008);
  a096=(a084-a096);
  a097=(a014*a021);
  a096=(a096-a097);
  a097=(a031*a083);
  a096=(a096-a097);
  a097=(a096/a023);
  a098=(a013*a008);
  a098=(a085-a098);
  a099=(a002*a021);
  a098=(a098-a099);
  a083=(a032*a083);
  a098=(a098-a083);
  a096=(a025*a096);
  a098=(a098-a096);
  a098=(a098/a024);
  a096=(a025*a098);
  a097=(a097-a096);
  a096=(a031*a097);
  a095=(a095-a096);
  a096=(a032*a098);
  a095=(a095-a096);
  a096=(a017*a095);
  a083=(a008/a000);
  a096=(a096-a083);
  a083=(a015*a097);
  a096=(a096+a083);
  a083=(a013*a098);
  a096=(a096+a083);
  a083=(a036*a096);
  a099=(a021/a000);
  a100=(a016*a095);
  a099=(a099-a100);
  a100=(a014*a097);
  a099=(a099-a100);
  a100=(a002*a098);
  a099=(a099-a100);
  a100=(a027*a099);
  a083=(a083-a100);
  a100=(a050*a095);
  a083=(a083+a100);
  a100=(a042*a097);
  a083=(a083+a100);
  a100=(a063*a098);
  a083=(a083+a100);
  if (res[1]!=0) res[1][12]=a083;
  a083=(a004*a099);
  a100=(a003*a096);
  a083=(a083-a100);
  a100=(a055*a095);
  a083=(a083+a100);
  if (res[1]!=0) res[1][13]=a083;
  a083=(a007*a099);
  a100=(a006*a096);
  a083=(a083-a100);
  a100=(a075*a095);
  a083=(a083+a100);
  a100=(a082*a097);
  a083=(a083+a100);
  if (res[1]!=0) res[1][14]=a083;
  a083=(a021*a099);
  a100=(a008*a096);
  a083=(a083-a100);
  a100=(a081*a095);
  a083=(a083+a100);
  a100=(a084*a097);
  a083=(a083+a100);
  a100=(a085*a098);
  a083=(a083+a100);
  if (res[1]!=0) res[1][15]=a083;
  a083=arg[1]? arg[1][3] : 0;
  a100=arg[1]? arg[1][2] : 0;
  a101=(a083+a100);
  a102=casadi_sq(a101);
  a103=(a102*a054);
  a104=casadi_sq(a100);
  a105=(a104*a028);
  a103=(a103+a105);
  a105=arg[6]? arg[6][1] : 0;
  a106=(a103*a105);
  a107=(a102*a058);
  a103=(a103+a107);
  a107=arg[1]? arg[1][4] : 0;
  a101=(a101+a107);
  a101=casadi_sq(a101);
  a108=(a060*a101);
  a103=(a103+a108);
  a108=arg[6]? arg[6][2] : 0;
  a103=(a103*a108);
  a109=(a106+a103);
  a110=(a109/a000);
  a111=(a017*a109);
  a112=(a030+a038);
  a113=(a041+a112);
  a114=(a045+a113);
  a115=(a048+a114);
  a115=(a103*a115);
  a116=(a102*a041);
  a030=(a104*a030);
  a116=(a116+a030);
  a045=(a102*a045);
  a045=(a116+a045);
  a030=(a048*a101);
  a045=(a045+a030);
  a028=(a028+a052);
  a030=(a054+a028);
  a058=(a058+a030);
  a117=(a060+a058);
  a117=(a045*a117);
  a117=(a117*a108);
  a115=(a115-a117);
  a116=(a116*a105);
  a030=(a116*a030);
  a030=(a115-a030);
  a106=(a106*a113);
  a030=(a030+a106);
  a038=(a109*a038);
  a038=(a030-a038);
  a045=(a045*a108);
  a116=(a116+a045);
  a052=(a116*a052);
  a038=(a038+a052);
  a111=(a111-a038);
  a038=(a016*a116);
  a111=(a111-a038);
  a029=(a111/a029);
  a038=arg[2]? arg[2][0] : 0;
  a112=(a109*a112);
  a030=(a030-a112);
  a028=(a116*a028);
  a030=(a030+a028);
  a038=(a038-a030);
  a030=(a015*a109);
  a038=(a038+a030);
  a030=(a014*a116);
  a038=(a038-a030);
  a030=(a031*a111);
  a038=(a038-a030);
  a023=(a038/a023);
  a030=arg[2]? arg[2][1] : 0;
  a103=(a103*a114);
  a115=(a115-a103);
  a045=(a045*a058);
  a115=(a115+a045);
  a030=(a030-a115);
  a109=(a013*a109);
  a030=(a030+a109);
  a109=(a002*a116);
  a030=(a030-a109);
  a111=(a032*a111);
  a030=(a030-a111);
  a038=(a025*a038);
  a030=(a030-a038);
  a030=(a030/a024);
  a025=(a025*a030);
  a023=(a023-a025);
  a031=(a031*a023);
  a029=(a029-a031);
  a032=(a032*a030);
  a029=(a029-a032);
  a017=(a017*a029);
  a110=(a110+a017);
  a015=(a015*a023);
  a110=(a110+a015);
  a013=(a013*a030);
  a110=(a110+a013);
  a036=(a036*a110);
  a116=(a116/a000);
  a016=(a016*a029);
  a116=(a116-a016);
  a014=(a014*a023);
  a116=(a116-a014);
  a002=(a002*a030);
  a116=(a116-a002);
  a027=(a027*a116);
  a036=(a036-a027);
  a050=(a050*a029);
  a036=(a036+a050);
  a042=(a042*a023);
  a036=(a036+a042);
  a063=(a063*a030);
  a036=(a036+a063);
  a063=arg[5]? arg[5][1] : 0;
  a063=(a063/a073);
  a042=(a009*a063);
  a050=arg[5]? arg[5][0] : 0;
  a050=(a050/a073);
  a073=(a034*a050);
  a042=(a042-a073);
  a073=arg[5]? arg[5][2] : 0;
  a073=(a073/a078);
  a077=(a077*a073);
  a042=(a042+a077);
  a036=(a036+a042);
  a042=arg[1]? arg[1][0] : 0;
  a077=(a035*a042);
  a044=(a044*a100);
  a077=(a077+a044);
  a046=(a046*a083);
  a077=(a077+a046);
  a067=(a067*a107);
  a077=(a077-a067);
  a077=(a009*a077);
  a067=(a035*a100);
  a053=(a053*a083);
  a067=(a067+a053);
  a053=(a005*a107);
  a067=(a067+a053);
  a053=(a077*a067);
  a040=(a102*a040);
  a046=(a007*a040);
  a104=(a104*a026);
  a026=(a004*a104);
  a046=(a046+a026);
  a026=(a046*a033);
  a102=(a102*a018);
  a018=(a007*a102);
  a018=(a046+a018);
  a047=(a047*a101);
  a022=(a022*a047);
  a018=(a018+a022);
  a022=(a018*a005);
  a026=(a026+a022);
  a026=(a034*a026);
  a053=(a053-a026);
  a026=arg[1]? arg[1][1] : 0;
  a035=(a035*a026);
  a057=(a057*a100);
  a035=(a035+a057);
  a068=(a068*a083);
  a035=(a035+a068);
  a072=(a072*a107);
  a035=(a035+a072);
  a035=(a034*a035);
  a072=(a035*a067);
  a053=(a053+a072);
  a077=(a077+a035);
  a069=(a069*a009);
  a066=(a034*a066);
  a035=(a069-a066);
  a072=arg[4]? arg[4][2] : 0;
  a068=(a035*a072);
  a077=(a077+a068);
  a068=arg[4]? arg[4][0] : 0;
  a068=(a009*a068);
  a077=(a077-a068);
  a057=arg[4]? arg[4][1] : 0;
  a034=(a034*a057);
  a077=(a077-a034);
  a057=(a071*a009);
  a022=(a019*a062);
  a022=(a022*a010);
  a057=(a057-a022);
  a022=(a057*a067);
  a077=(a077-a022);
  a077=(a067*a077);
  a053=(a053+a077);
  a035=(a035*a067);
  a066=(a066-a069);
  a066=(a072*a066);
  a035=(a035+a066);
  a072=(a072*a035);
  a053=(a053+a072);
  a068=(a068*a067);
  a053=(a053-a068);
  a034=(a034*a067);
  a053=(a053-a034);
  a040=(a040*a011);
  a104=(a104*a003);
  a040=(a040+a104);
  a033=(a040*a033);
  a102=(a102*a011);
  a102=(a040+a102);
  a047=(a047*a012);
  a102=(a102+a047);
  a005=(a102*a005);
  a033=(a033+a005);
  a009=(a009*a033);
  a053=(a053+a009);
  a036=(a036+a053);
  if (res[2]!=0) res[2][0]=a036;
  a036=(a004*a116);
  a053=(a003*a110);
  a036=(a036-a053);
  a055=(a055*a029);
  a036=(a036+a055);
  a003=(a003*a026);
  a003=(a003*a100);
  a004=(a004*a042);
  a004=(a004*a100);
  a003=(a003+a004);
  a036=(a036-a003);
  if (res[2]!=0) res[2][1]=a036;
  a036=(a007*a116);
  a003=(a006*a110);
  a036=(a036-a003);
  a075=(a075*a029);
  a036=(a036+a075);
  a082=(a082*a023);
  a036=(a036+a082);
  a046=(a006*a046);
  a040=(a007*a040);
  a046=(a046-a040);
  a056=(a056*a100);
  a056=(a026+a056);
  a054=(a054*a083);
  a056=(a056+a054);
  a006=(a006*a056);
  a056=(a100+a083);
  a006=(a006*a056);
  a046=(a046-a006);
  a043=(a043*a100);
  a043=(a042+a043);
  a041=(a041*a083);
  a043=(a043-a041);
  a007=(a007*a043);
  a007=(a007*a056);
  a046=(a046-a007);
  a036=(a036+a046);
  if (res[2]!=0) res[2][2]=a036;
  a036=(a021*a116);
  a046=(a008*a110);
  a036=(a036-a046);
  a081=(a081*a029);
  a036=(a036+a081);
  a084=(a084*a023);
  a036=(a036+a084);
  a085=(a085*a030);
  a036=(a036+a085);
  a018=(a008*a018);
  a102=(a021*a102);
  a018=(a018-a102);
  a061=(a061*a100);
  a026=(a026+a061);
  a059=(a059*a083);
  a026=(a026+a059);
  a060=(a060*a107);
  a026=(a026+a060);
  a008=(a008*a026);
  a056=(a056+a107);
  a008=(a008*a056);
  a018=(a018-a008);
  a049=(a049*a100);
  a042=(a042+a049);
  a039=(a039*a083);
  a042=(a042+a039);
  a048=(a048*a107);
  a042=(a042-a048);
  a021=(a021*a042);
  a021=(a021*a056);
  a018=(a018-a021);
  a036=(a036+a018);
  if (res[2]!=0) res[2][3]=a036;
  if (res[3]!=0) res[3][0]=a110;
  if (res[3]!=0) res[3][1]=a116;
  if (res[3]!=0) res[3][2]=a029;
  if (res[3]!=0) res[3][3]=a023;
  if (res[3]!=0) res[3][4]=a030;
  if (res[4]!=0) res[4][0]=a050;
  if (res[4]!=0) res[4][1]=a063;
  if (res[4]!=0) res[4][2]=a073;
  if (res[5]!=0) res[5][0]=a037;
  a020=(-a020);
  if (res[5]!=0) res[5][1]=a020;
  if (res[5]!=0) res[5][2]=a064;
  if (res[5]!=0) res[5][3]=a065;
  if (res[5]!=0) res[5][4]=a070;
  if (res[5]!=0) res[5][5]=a088;
  if (res[5]!=0) res[5][6]=a089;
  if (res[5]!=0) res[5][7]=a080;
  a087=(-a087);
  if (res[5]!=0) res[5][8]=a087;
  if (res[5]!=0) res[5][9]=a086;
  if (res[5]!=0) res[5][10]=a091;
  if (res[5]!=0) res[5][11]=a094;
  if (res[5]!=0) res[5][12]=a090;
  if (res[5]!=0) res[5][13]=a092;
  a093=(-a093);
  if (res[5]!=0) res[5][14]=a093;
  if (res[5]!=0) res[5][15]=a096;
  if (res[5]!=0) res[5][16]=a099;
  if (res[5]!=0) res[5][17]=a095;
  if (res[5]!=0) res[5][18]=a097;
  if (res[5]!=0) res[5][19]=a098;
  a074=(-a074);
  if (res[6]!=0) res[6][0]=a074;
  if (res[6]!=0) res[6][1]=a076;
  if (res[6]!=0) res[6][2]=a079;
  if (res[6]!=0) res[6][3]=a001;
  if (res[6]!=0) res[6][4]=a001;
  if (res[6]!=0) res[6][5]=a001;
  if (res[6]!=0) res[6][6]=a001;
  if (res[6]!=0) res[6][7]=a001;
  if (res[6]!=0) res[6][8]=a001;
  if (res[6]!=0) res[6][9]=a001;
  if (res[6]!=0) res[6][10]=a001;
  if (res[6]!=0) res[6][11]=a001;
  if (res[7]!=0) res[7][0]=a057;
  a019=(a019*a071);
  a051=(a051*a062);
  a019=(a019+a051);
  if (res[8]!=0) res[8][0]=a019;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_contact_system_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_contact_system_n_in(void) { return 16;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_contact_system_n_out(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na2_contact_system_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_contact_system_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "tau";
    case 3: return "q_obj";
    case 4: return "v_obj";
    case 5: return "f_obj";
    case 6: return "K";
    case 7: return "contact_link";
    case 8: return "side";
    case 9: return "object_mass";
    case 10: return "object_inertia";
    case 11: return "rho";
    case 12: return "wheel_offset";
    case 13: return "contact_offset";
    case 14: return "object_distance";
    case 15: return "placed";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_contact_system_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    case 1: return "delassus";
    case 2: return "b";
    case 3: return "qdd_free";
    case 4: return "a_obj_free";
    case 5: return "qdd_from_lam";
    case 6: return "a_obj_from_lam";
    case 7: return "gap";
    case 8: return "s";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_contact_system_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    case 4: return casadi_s2;
    case 5: return casadi_s2;
    case 6: return casadi_s3;
    case 7: return casadi_s2;
    case 8: return casadi_s4;
    case 9: return casadi_s4;
    case 10: return casadi_s4;
    case 11: return casadi_s1;
    case 12: return casadi_s2;
    case 13: return casadi_s4;
    case 14: return casadi_s4;
    case 15: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_contact_system_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s6;
    case 2: return casadi_s7;
    case 3: return casadi_s0;
    case 4: return casadi_s2;
    case 5: return casadi_s8;
    case 6: return casadi_s9;
    case 7: return casadi_s4;
    case 8: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16;
  if (sz_res) *sz_res = 9;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 9*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

CASADI_SYMBOL_EXPORT int snakecg_na2_batch_contact_system(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[16];
  casadi_real* r[9];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 119);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 16; ++k) a[k] = 0;
  for (k = 0; k < 9; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    a[7] = arg[7] + i * stride[7];
    a[8] = arg[8] + i * stride[8];
    a[9] = arg[9] + i * stride[9];
    a[10] = arg[10] + i * stride[10];
    a[11] = arg[11] + i * stride[11];
    a[12] = arg[12] + i * stride[12];
    a[13] = arg[13] + i * stride[13];
    a[14] = arg[14] + i * stride[14];
    a[15] = arg[15] + i * stride[15];
    r[0] = res[0] + i * 25;
    r[1] = res[1] + i * 16;
    r[2] = res[2] + i * 4;
    r[3] = res[3] + i * 5;
    r[4] = res[4] + i * 3;
    r[5] = res[5] + i * 20;
    r[6] = res[6] + i * 12;
    r[7] = res[7] + i * 1;
    r[8] = res[8] + i * 1;
    if (snakecg_na2_contact_system(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
