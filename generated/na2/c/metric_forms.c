/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for metric_forms() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 4e89dd687d4cbc8709e9cfd98d262e9a276cb64607f251a625473028d4ba2314
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na2_metric_forms_ ## ID
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
#define casadi_fmin CASADI_PREFIX(fmin)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
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

casadi_real casadi_fmin(casadi_real x, casadi_real y) {
/* Pre-c99 compatibility */
#if __STDC_VERSION__ < 199901L
  return x<y ? x : y;
#else
  return fmin(x, y);
#endif
}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {5, 1, 1};
static const casadi_int casadi_s1[3] = {25, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {2, 1, 1};
static const casadi_int casadi_s5[3] = {4, 1, 1};
static const casadi_int casadi_s6[3] = {2, 2, 1};
static const casadi_int casadi_s7[3] = {1, 2, 1};

/* snakecg_na2_metric_forms:(q[5],K[25],contact_link[3],side,object_mass,object_inertia,q_obj[3],rho[2],wheel_offset[3],free[4],regularization)->(omega_tau[2x2],xi_tau[2x2],lambda_form_tau[2x2],input_metric[2x2],contact_from_tau[1x2],pivot_ratio) */
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
  casadi_real a108;
  a000=arg[0]? arg[0][2] : 0;
  a001=arg[2]? arg[2][0] : 0;
  a002=(a000*a001);
  a003=arg[0]? arg[0][3] : 0;
  a004=(a003+a000);
  a005=arg[2]? arg[2][1] : 0;
  a006=(a004*a005);
  a002=(a002+a006);
  a006=arg[0]? arg[0][4] : 0;
  a007=(a004+a006);
  a008=arg[2]? arg[2][2] : 0;
  a009=(a007*a008);
  a002=(a002+a009);
  a009=sin(a002);
  a010=arg[3]? arg[3][0] : 0;
  a011=(a009*a010);
  a012=arg[4]? arg[4][0] : 0;
  a013=(a011/a012);
  a014=arg[9]? arg[9][0] : 0;
  a015=(a001+a005);
  a015=(a015+a008);
  a016=(a011*a015);
  a017=arg[1]? arg[1][15] : 0;
  a018=cos(a000);
  a019=cos(a003);
  a020=(a018*a019);
  a000=sin(a000);
  a003=sin(a003);
  a021=(a000*a003);
  a020=(a020-a021);
  a021=sin(a006);
  a022=(a020*a021);
  a006=cos(a006);
  a003=(a018*a003);
  a019=(a019*a000);
  a003=(a003+a019);
  a019=(a006*a003);
  a022=(a022+a019);
  a019=(a017*a022);
  a023=arg[1]? arg[1][14] : 0;
  a024=(a023*a003);
  a024=(a019+a024);
  a025=arg[1]? arg[1][13] : 0;
  a026=(a025*a000);
  a026=(a024+a026);
  a027=arg[1]? arg[1][12] : 0;
  a028=(a026/a027);
  a006=(a020*a006);
  a021=(a003*a021);
  a006=(a006-a021);
  a017=(a017*a006);
  a021=arg[1]? arg[1][4] : 0;
  a029=(a020*a021);
  a029=(a017*a029);
  a030=(a003*a021);
  a030=(a019*a030);
  a029=(a029+a030);
  a030=arg[1]? arg[1][24] : 0;
  a031=(a029+a030);
  a032=arg[1]? arg[1][3] : 0;
  a033=arg[1]? arg[1][9] : 0;
  a032=(a032-a033);
  a034=(a018*a032);
  a035=(a017*a034);
  a032=(a032*a000);
  a036=(a019*a032);
  a035=(a035+a036);
  a035=(a031+a035);
  a036=(a019/a027);
  a037=(a036*a028);
  a037=(a037*a027);
  a037=(a035-a037);
  a038=(a017/a027);
  a023=(a023*a020);
  a023=(a017+a023);
  a025=(a025*a018);
  a025=(a023+a025);
  a039=(a025/a027);
  a040=(a038*a039);
  a040=(a040*a027);
  a037=(a037-a040);
  a029=(a031+a029);
  a040=arg[1]? arg[1][23] : 0;
  a029=(a029+a040);
  a040=(a023*a034);
  a041=(a024*a032);
  a040=(a040+a041);
  a041=(a029+a040);
  a040=(a041+a040);
  a042=arg[1]? arg[1][22] : 0;
  a040=(a040+a042);
  a042=casadi_sq(a028);
  a042=(a042*a027);
  a042=(a040-a042);
  a043=casadi_sq(a039);
  a043=(a043*a027);
  a042=(a042-a043);
  a037=(a037/a042);
  a043=(a024/a027);
  a044=(a036*a043);
  a044=(a044*a027);
  a044=(a031-a044);
  a045=(a023/a027);
  a046=(a038*a045);
  a046=(a046*a027);
  a044=(a044-a046);
  a046=(a043*a028);
  a046=(a046*a027);
  a046=(a041-a046);
  a047=(a045*a039);
  a047=(a047*a027);
  a046=(a046-a047);
  a046=(a046/a042);
  a047=(a037*a046);
  a047=(a047*a042);
  a044=(a044-a047);
  a047=casadi_sq(a043);
  a047=(a047*a027);
  a047=(a029-a047);
  a048=casadi_sq(a045);
  a048=(a048*a027);
  a047=(a047-a048);
  a048=casadi_sq(a046);
  a048=(a048*a042);
  a047=(a047-a048);
  a044=(a044/a047);
  a048=casadi_sq(a036);
  a048=(a048*a027);
  a048=(a030-a048);
  a049=casadi_sq(a038);
  a049=(a049*a027);
  a048=(a048-a049);
  a049=casadi_sq(a037);
  a049=(a049*a042);
  a048=(a048-a049);
  a049=casadi_sq(a044);
  a049=(a049*a047);
  a048=(a048-a049);
  a049=(a044/a048);
  a050=(a037*a049);
  a051=(1./a047);
  a052=(a044*a049);
  a051=(a051+a052);
  a052=(a046*a051);
  a050=(a050-a052);
  a052=(a028*a050);
  a053=(a043*a051);
  a052=(a052+a053);
  a053=(a036*a049);
  a052=(a052-a053);
  a053=(a016*a052);
  a002=cos(a002);
  a054=(a002*a010);
  a055=(a054*a015);
  a056=(a038*a049);
  a057=(a039*a050);
  a058=(a045*a051);
  a057=(a057+a058);
  a056=(a056-a057);
  a057=(a055*a056);
  a053=(a053-a057);
  a057=arg[0]? arg[0][1] : 0;
  a032=(a057+a032);
  a058=arg[1]? arg[1][10] : 0;
  a059=(a003*a058);
  a060=(a032+a059);
  a061=(a057-a060);
  a062=(a005*a061);
  a021=(a021-a058);
  a003=(a021*a003);
  a003=(a060+a003);
  a063=arg[1]? arg[1][11] : 0;
  a022=(a022*a063);
  a003=(a003+a022);
  a064=(a057-a003);
  a065=(a008*a064);
  a062=(a062+a065);
  a062=(a011*a062);
  a065=arg[0]? arg[0][0] : 0;
  a034=(a065+a034);
  a066=(a020*a058);
  a067=(a034+a066);
  a068=(a067-a065);
  a069=(a005*a068);
  a020=(a020*a021);
  a020=(a067+a020);
  a006=(a006*a063);
  a020=(a020+a006);
  a021=(a020-a065);
  a070=(a008*a021);
  a069=(a069+a070);
  a069=(a054*a069);
  a062=(a062-a069);
  a033=(a033*a001);
  a058=(a058*a005);
  a033=(a033+a058);
  a063=(a063*a008);
  a033=(a033+a063);
  a063=(a010*a033);
  a058=arg[6]? arg[6][2] : 0;
  a069=cos(a058);
  a070=arg[7]? arg[7][1] : 0;
  a071=(a069*a070);
  a058=sin(a058);
  a072=arg[7]? arg[7][0] : 0;
  a073=(a058*a072);
  a071=(a071+a073);
  a073=arg[6]? arg[6][1] : 0;
  a073=(a071+a073);
  a009=(a009*a033);
  a073=(a073+a009);
  a057=(a057*a001);
  a060=(a060*a005);
  a057=(a057+a060);
  a060=(a003*a008);
  a057=(a057+a060);
  a073=(a073-a057);
  a073=(a011*a073);
  a063=(a063-a073);
  a069=(a069*a072);
  a058=(a058*a070);
  a069=(a069-a058);
  a058=arg[6]? arg[6][0] : 0;
  a058=(a069+a058);
  a033=(a002*a033);
  a058=(a058+a033);
  a065=(a065*a001);
  a067=(a067*a005);
  a065=(a065+a067);
  a067=(a020*a008);
  a065=(a065+a067);
  a058=(a058-a065);
  a058=(a054*a058);
  a063=(a063-a058);
  a015=(a063*a015);
  a062=(a062+a015);
  a015=(a062*a050);
  a053=(a053+a015);
  a032=(a032-a003);
  a003=(a008*a032);
  a015=(a005*a059);
  a003=(a003-a015);
  a003=(a011*a003);
  a015=(a005*a066);
  a020=(a020-a034);
  a034=(a008*a020);
  a015=(a015+a034);
  a015=(a054*a015);
  a003=(a003-a015);
  a005=(a005+a008);
  a005=(a063*a005);
  a003=(a003+a005);
  a005=(a003*a051);
  a053=(a053+a005);
  a063=(a063*a008);
  a005=(a008*a022);
  a005=(a011*a005);
  a008=(a008*a006);
  a008=(a054*a008);
  a005=(a005+a008);
  a063=(a063-a005);
  a005=(a063*a049);
  a053=(a053-a005);
  a053=(a014*a053);
  a005=(a016/a027);
  a008=(a028*a016);
  a008=(a062+a008);
  a015=(a039*a055);
  a008=(a008+a015);
  a015=(a008/a042);
  a034=(a043*a016);
  a034=(a003+a034);
  a058=(a045*a055);
  a034=(a034+a058);
  a058=(a046*a008);
  a034=(a034-a058);
  a058=(a034/a047);
  a065=(a036*a016);
  a065=(a063+a065);
  a067=(a038*a055);
  a065=(a065+a067);
  a008=(a037*a008);
  a065=(a065-a008);
  a034=(a044*a034);
  a065=(a065-a034);
  a065=(a065/a048);
  a034=(a044*a065);
  a058=(a058-a034);
  a034=(a046*a058);
  a015=(a015-a034);
  a034=(a037*a065);
  a015=(a015-a034);
  a034=(a028*a015);
  a005=(a005+a034);
  a034=(a043*a058);
  a005=(a005+a034);
  a034=(a036*a065);
  a005=(a005+a034);
  a034=(a016*a005);
  a008=(a055/a027);
  a067=(a039*a015);
  a008=(a008+a067);
  a067=(a045*a058);
  a008=(a008+a067);
  a067=(a038*a065);
  a008=(a008+a067);
  a067=(a055*a008);
  a034=(a034+a067);
  a067=(a062*a015);
  a034=(a034+a067);
  a067=(a003*a058);
  a034=(a034+a067);
  a067=(a063*a065);
  a034=(a034+a067);
  a067=(a011*a013);
  a001=(a054/a012);
  a054=(a054*a001);
  a067=(a067+a054);
  a002=(a002*a069);
  a002=(a002*a010);
  a011=(a011*a071);
  a002=(a002+a011);
  a011=arg[5]? arg[5][0] : 0;
  a071=(a002/a011);
  a002=(a002*a071);
  a067=(a067+a002);
  a034=(a034+a067);
  a067=(a014*a034);
  a067=(a067*a014);
  a002=1.;
  a010=(a002-a014);
  a067=(a067+a010);
  a010=arg[10]? arg[10][0] : 0;
  a069=(a010*a014);
  a067=(a067+a069);
  a069=(a053/a067);
  a054=arg[9]? arg[9][1] : 0;
  a033=arg[8]? arg[8][0] : 0;
  a070=(a033*a015);
  a072=(a000*a005);
  a073=(a018*a008);
  a072=(a072+a073);
  a070=(a070-a072);
  a072=(a054*a070);
  a072=(a072*a014);
  a072=(a072/a067);
  a073=(a018*a056);
  a057=(a000*a052);
  a073=(a073-a057);
  a057=(a033*a050);
  a073=(a073+a057);
  a073=(a054*a073);
  a057=(a072*a053);
  a073=(a073-a057);
  a057=(a018/a027);
  a060=(a028*a000);
  a060=(a033-a060);
  a009=(a039*a018);
  a060=(a060-a009);
  a009=(a060/a042);
  a074=(a043*a000);
  a075=(a045*a018);
  a074=(a074+a075);
  a075=(a046*a060);
  a074=(a074+a075);
  a075=(a074/a047);
  a074=(a044*a074);
  a076=(a036*a000);
  a077=(a038*a018);
  a076=(a076+a077);
  a060=(a037*a060);
  a076=(a076+a060);
  a074=(a074-a076);
  a074=(a074/a048);
  a076=(a044*a074);
  a075=(a075+a076);
  a076=(a046*a075);
  a009=(a009+a076);
  a076=(a037*a074);
  a009=(a009-a076);
  a076=(a039*a009);
  a057=(a057-a076);
  a076=(a045*a075);
  a057=(a057+a076);
  a076=(a038*a074);
  a057=(a057-a076);
  a076=(a018*a057);
  a060=(a028*a009);
  a077=(a000/a027);
  a060=(a060-a077);
  a077=(a043*a075);
  a060=(a060-a077);
  a077=(a036*a074);
  a060=(a060+a077);
  a077=(a000*a060);
  a076=(a076-a077);
  a077=(a033*a009);
  a076=(a076+a077);
  a077=(a054*a076);
  a077=(a077*a054);
  a078=(a002-a054);
  a077=(a077+a078);
  a078=(a010*a054);
  a077=(a077+a078);
  a078=casadi_sq(a072);
  a078=(a078*a067);
  a078=(a077-a078);
  a079=(a073/a078);
  a080=arg[9]? arg[9][2] : 0;
  a081=cos(a004);
  a082=(a081*a057);
  a004=sin(a004);
  a083=(a004*a060);
  a082=(a082-a083);
  a068=(a081*a068);
  a061=(a004*a061);
  a068=(a068-a061);
  a061=arg[8]? arg[8][1] : 0;
  a068=(a068+a061);
  a083=(a068*a009);
  a082=(a082+a083);
  a059=(a004*a059);
  a066=(a081*a066);
  a059=(a059+a066);
  a059=(a059+a061);
  a061=(a059*a075);
  a082=(a082-a061);
  a061=(a080*a082);
  a061=(a061*a054);
  a066=(a068*a015);
  a083=(a004*a005);
  a084=(a081*a008);
  a083=(a083+a084);
  a066=(a066-a083);
  a083=(a059*a058);
  a066=(a066+a083);
  a083=(a080*a066);
  a083=(a083*a014);
  a083=(a083/a067);
  a084=(a083*a072);
  a084=(a084*a067);
  a061=(a061-a084);
  a061=(a061/a078);
  a084=(a081*a056);
  a085=(a004*a052);
  a084=(a084-a085);
  a085=(a068*a050);
  a084=(a084+a085);
  a085=(a059*a051);
  a084=(a084+a085);
  a084=(a080*a084);
  a085=(a083*a053);
  a084=(a084-a085);
  a085=(a061*a073);
  a084=(a084-a085);
  a085=(a081/a027);
  a086=(a028*a004);
  a086=(a068-a086);
  a087=(a039*a081);
  a086=(a086-a087);
  a087=(a086/a042);
  a088=(a043*a004);
  a088=(a059-a088);
  a089=(a045*a081);
  a088=(a088-a089);
  a089=(a046*a086);
  a088=(a088-a089);
  a089=(a088/a047);
  a090=(a036*a004);
  a091=(a038*a081);
  a090=(a090+a091);
  a086=(a037*a086);
  a090=(a090+a086);
  a088=(a044*a088);
  a090=(a090+a088);
  a090=(a090/a048);
  a088=(a044*a090);
  a089=(a089+a088);
  a088=(a046*a089);
  a087=(a087-a088);
  a088=(a037*a090);
  a087=(a087+a088);
  a088=(a039*a087);
  a085=(a085-a088);
  a088=(a045*a089);
  a085=(a085-a088);
  a088=(a038*a090);
  a085=(a085+a088);
  a088=(a081*a085);
  a086=(a028*a087);
  a091=(a004/a027);
  a086=(a086-a091);
  a091=(a043*a089);
  a086=(a086+a091);
  a091=(a036*a090);
  a086=(a086-a091);
  a091=(a004*a086);
  a088=(a088-a091);
  a091=(a068*a087);
  a088=(a088+a091);
  a091=(a059*a089);
  a088=(a088+a091);
  a091=(a080*a088);
  a091=(a091*a080);
  a092=(a002-a080);
  a091=(a091+a092);
  a092=(a010*a080);
  a091=(a091+a092);
  a092=casadi_sq(a083);
  a092=(a092*a067);
  a092=(a091-a092);
  a093=casadi_sq(a061);
  a093=(a093*a078);
  a092=(a092-a093);
  a093=(a084/a092);
  a094=arg[9]? arg[9][3] : 0;
  a095=cos(a007);
  a096=(a095*a085);
  a007=sin(a007);
  a097=(a007*a086);
  a096=(a096-a097);
  a021=(a095*a021);
  a064=(a007*a064);
  a021=(a021-a064);
  a064=arg[8]? arg[8][2] : 0;
  a021=(a021+a064);
  a097=(a021*a087);
  a096=(a096+a097);
  a020=(a095*a020);
  a032=(a007*a032);
  a020=(a020-a032);
  a020=(a020+a064);
  a032=(a020*a089);
  a096=(a096+a032);
  a022=(a007*a022);
  a006=(a095*a006);
  a022=(a022+a006);
  a022=(a022+a064);
  a064=(a022*a090);
  a096=(a096-a064);
  a064=(a094*a096);
  a064=(a064*a080);
  a006=(a021*a015);
  a032=(a007*a005);
  a097=(a095*a008);
  a032=(a032+a097);
  a006=(a006-a032);
  a032=(a020*a058);
  a006=(a006+a032);
  a032=(a022*a065);
  a006=(a006+a032);
  a032=(a094*a006);
  a032=(a032*a014);
  a032=(a032/a067);
  a097=(a032*a083);
  a097=(a097*a067);
  a064=(a064-a097);
  a097=(a095*a057);
  a098=(a007*a060);
  a097=(a097-a098);
  a098=(a021*a009);
  a097=(a097+a098);
  a098=(a020*a075);
  a097=(a097-a098);
  a098=(a022*a074);
  a097=(a097+a098);
  a098=(a094*a097);
  a098=(a098*a054);
  a099=(a032*a072);
  a099=(a099*a067);
  a098=(a098-a099);
  a098=(a098/a078);
  a099=(a098*a061);
  a099=(a099*a078);
  a064=(a064-a099);
  a064=(a064/a092);
  a099=(a095*a056);
  a100=(a007*a052);
  a099=(a099-a100);
  a100=(a021*a050);
  a099=(a099+a100);
  a100=(a020*a051);
  a099=(a099+a100);
  a100=(a022*a049);
  a099=(a099-a100);
  a099=(a094*a099);
  a053=(a032*a053);
  a099=(a099-a053);
  a073=(a098*a073);
  a099=(a099-a073);
  a084=(a064*a084);
  a099=(a099-a084);
  a084=(a095/a027);
  a073=(a028*a007);
  a073=(a021-a073);
  a053=(a039*a095);
  a073=(a073-a053);
  a042=(a073/a042);
  a053=(a043*a007);
  a053=(a020-a053);
  a100=(a045*a095);
  a053=(a053-a100);
  a100=(a046*a073);
  a053=(a053-a100);
  a047=(a053/a047);
  a100=(a036*a007);
  a100=(a022-a100);
  a101=(a038*a095);
  a100=(a100-a101);
  a073=(a037*a073);
  a100=(a100-a073);
  a053=(a044*a053);
  a100=(a100-a053);
  a100=(a100/a048);
  a044=(a044*a100);
  a047=(a047-a044);
  a044=(a046*a047);
  a042=(a042-a044);
  a044=(a037*a100);
  a042=(a042-a044);
  a044=(a039*a042);
  a084=(a084-a044);
  a044=(a045*a047);
  a084=(a084-a044);
  a044=(a038*a100);
  a084=(a084-a044);
  a044=(a095*a084);
  a053=(a028*a042);
  a073=(a007/a027);
  a053=(a053-a073);
  a073=(a043*a047);
  a053=(a053+a073);
  a073=(a036*a100);
  a053=(a053+a073);
  a073=(a007*a053);
  a044=(a044-a073);
  a073=(a021*a042);
  a044=(a044+a073);
  a073=(a020*a047);
  a044=(a044+a073);
  a073=(a022*a100);
  a044=(a044+a073);
  a073=(a094*a044);
  a073=(a073*a094);
  a101=(a002-a094);
  a073=(a073+a101);
  a010=(a010*a094);
  a073=(a073+a010);
  a010=casadi_sq(a032);
  a010=(a010*a067);
  a010=(a073-a010);
  a101=casadi_sq(a098);
  a101=(a101*a078);
  a010=(a010-a101);
  a101=casadi_sq(a064);
  a101=(a101*a092);
  a010=(a010-a101);
  a099=(a099/a010);
  a101=(a064*a099);
  a093=(a093-a101);
  a101=(a061*a093);
  a079=(a079-a101);
  a101=(a098*a099);
  a079=(a079-a101);
  a101=(a072*a079);
  a069=(a069-a101);
  a101=(a083*a093);
  a069=(a069-a101);
  a101=(a032*a099);
  a069=(a069-a101);
  a101=(a013*a069);
  a102=(a101*a012);
  a103=(a102*a101);
  a104=(a001*a069);
  a105=(a104*a012);
  a106=(a105*a104);
  a103=(a103+a106);
  a106=(a071*a069);
  a107=(a106*a011);
  a108=(a107*a106);
  a103=(a103+a108);
  if (res[0]!=0) res[0][0]=a103;
  a046=(a046*a049);
  a037=(a037/a048);
  a046=(a046-a037);
  a028=(a028*a046);
  a043=(a043*a049);
  a028=(a028-a043);
  a036=(a036/a048);
  a028=(a028+a036);
  a036=(a016*a028);
  a045=(a045*a049);
  a039=(a039*a046);
  a045=(a045-a039);
  a038=(a038/a048);
  a045=(a045-a038);
  a038=(a055*a045);
  a036=(a036-a038);
  a038=(a062*a046);
  a036=(a036+a038);
  a038=(a003*a049);
  a036=(a036-a038);
  a038=(a063/a048);
  a036=(a036+a038);
  a014=(a014*a036);
  a067=(a014/a067);
  a036=(a018*a045);
  a038=(a000*a028);
  a036=(a036-a038);
  a038=(a033*a046);
  a036=(a036+a038);
  a054=(a054*a036);
  a036=(a072*a014);
  a054=(a054-a036);
  a036=(a054/a078);
  a038=(a081*a045);
  a039=(a004*a028);
  a038=(a038-a039);
  a039=(a068*a046);
  a038=(a038+a039);
  a039=(a059*a049);
  a038=(a038-a039);
  a080=(a080*a038);
  a038=(a083*a014);
  a080=(a080-a038);
  a038=(a061*a054);
  a080=(a080-a038);
  a038=(a080/a092);
  a095=(a095*a045);
  a007=(a007*a028);
  a095=(a095-a007);
  a021=(a021*a046);
  a095=(a095+a021);
  a020=(a020*a049);
  a095=(a095-a020);
  a022=(a022/a048);
  a095=(a095+a022);
  a094=(a094*a095);
  a014=(a032*a014);
  a094=(a094-a014);
  a054=(a098*a054);
  a094=(a094-a054);
  a080=(a064*a080);
  a094=(a094-a080);
  a094=(a094/a010);
  a064=(a064*a094);
  a038=(a038-a064);
  a061=(a061*a038);
  a036=(a036-a061);
  a098=(a098*a094);
  a036=(a036-a098);
  a072=(a072*a036);
  a067=(a067-a072);
  a083=(a083*a038);
  a067=(a067-a083);
  a032=(a032*a094);
  a067=(a067-a032);
  a013=(a013*a067);
  a032=(a013*a012);
  a101=(a032*a101);
  a001=(a001*a067);
  a012=(a001*a012);
  a104=(a012*a104);
  a101=(a101+a104);
  a071=(a071*a067);
  a011=(a071*a011);
  a106=(a011*a106);
  a101=(a101+a106);
  if (res[0]!=0) res[0][1]=a101;
  a102=(a102*a013);
  a105=(a105*a001);
  a102=(a102+a105);
  a107=(a107*a071);
  a102=(a102+a107);
  if (res[0]!=0) res[0][2]=a102;
  a032=(a032*a013);
  a012=(a012*a001);
  a032=(a032+a012);
  a011=(a011*a071);
  a032=(a032+a011);
  if (res[0]!=0) res[0][3]=a032;
  a032=(a005*a069);
  a011=(a060*a079);
  a032=(a032+a011);
  a011=(a086*a093);
  a032=(a032+a011);
  a011=(a053*a099);
  a032=(a032+a011);
  a052=(a052-a032);
  a032=(a052*a027);
  a011=(a015*a069);
  a071=(a009*a079);
  a011=(a011+a071);
  a071=(a087*a093);
  a011=(a011+a071);
  a071=(a042*a099);
  a011=(a011+a071);
  a050=(a050-a011);
  a011=(a050*a026);
  a032=(a032-a011);
  a011=(a075*a079);
  a071=(a058*a069);
  a011=(a011-a071);
  a071=(a089*a093);
  a011=(a011-a071);
  a071=(a047*a099);
  a011=(a011-a071);
  a011=(a051+a011);
  a071=(a011*a024);
  a032=(a032-a071);
  a071=(a090*a093);
  a012=(a065*a069);
  a001=(a074*a079);
  a012=(a012+a001);
  a071=(a071-a012);
  a012=(a100*a099);
  a071=(a071-a012);
  a071=(a071-a049);
  a012=(a071*a019);
  a032=(a032-a012);
  a012=(a032*a052);
  a001=(a008*a069);
  a013=(a057*a079);
  a001=(a001-a013);
  a013=(a085*a093);
  a001=(a001-a013);
  a013=(a084*a099);
  a001=(a001-a013);
  a056=(a056+a001);
  a001=(a056*a027);
  a013=(a050*a025);
  a001=(a001+a013);
  a013=(a011*a023);
  a001=(a001+a013);
  a013=(a071*a017);
  a001=(a001+a013);
  a013=(a001*a056);
  a012=(a012+a013);
  a013=(a056*a025);
  a102=(a052*a026);
  a013=(a013-a102);
  a102=(a050*a040);
  a013=(a013+a102);
  a102=(a011*a041);
  a013=(a013+a102);
  a102=(a071*a035);
  a013=(a013+a102);
  a102=(a013*a050);
  a012=(a012+a102);
  a102=(a056*a023);
  a107=(a052*a024);
  a102=(a102-a107);
  a107=(a050*a041);
  a102=(a102+a107);
  a107=(a011*a029);
  a102=(a102+a107);
  a107=(a071*a031);
  a102=(a102+a107);
  a107=(a102*a011);
  a012=(a012+a107);
  a107=(a056*a017);
  a105=(a052*a019);
  a107=(a107-a105);
  a105=(a050*a035);
  a107=(a107+a105);
  a105=(a011*a031);
  a107=(a107+a105);
  a105=(a071*a030);
  a107=(a107+a105);
  a105=(a107*a071);
  a012=(a012+a105);
  if (res[1]!=0) res[1][0]=a012;
  a005=(a005*a067);
  a012=(a060*a036);
  a005=(a005+a012);
  a012=(a086*a038);
  a005=(a005+a012);
  a012=(a053*a094);
  a005=(a005+a012);
  a028=(a028-a005);
  a005=(a028*a027);
  a015=(a015*a067);
  a012=(a009*a036);
  a015=(a015+a012);
  a012=(a087*a038);
  a015=(a015+a012);
  a012=(a042*a094);
  a015=(a015+a012);
  a046=(a046-a015);
  a015=(a046*a026);
  a005=(a005-a015);
  a015=(a075*a036);
  a058=(a058*a067);
  a015=(a015-a058);
  a058=(a089*a038);
  a015=(a015-a058);
  a058=(a047*a094);
  a015=(a015-a058);
  a015=(a015-a049);
  a058=(a015*a024);
  a005=(a005-a058);
  a048=(1./a048);
  a058=(a090*a038);
  a065=(a065*a067);
  a012=(a074*a036);
  a065=(a065+a012);
  a058=(a058-a065);
  a065=(a100*a094);
  a058=(a058-a065);
  a058=(a048+a058);
  a065=(a058*a019);
  a005=(a005-a065);
  a052=(a005*a052);
  a008=(a008*a067);
  a065=(a057*a036);
  a008=(a008-a065);
  a065=(a085*a038);
  a008=(a008-a065);
  a065=(a084*a094);
  a008=(a008-a065);
  a045=(a045+a008);
  a027=(a045*a027);
  a008=(a046*a025);
  a027=(a027+a008);
  a008=(a015*a023);
  a027=(a027+a008);
  a008=(a058*a017);
  a027=(a027+a008);
  a056=(a027*a056);
  a052=(a052+a056);
  a025=(a045*a025);
  a026=(a028*a026);
  a025=(a025-a026);
  a040=(a046*a040);
  a025=(a025+a040);
  a040=(a015*a041);
  a025=(a025+a040);
  a040=(a058*a035);
  a025=(a025+a040);
  a050=(a025*a050);
  a052=(a052+a050);
  a023=(a045*a023);
  a024=(a028*a024);
  a023=(a023-a024);
  a041=(a046*a041);
  a023=(a023+a041);
  a029=(a015*a029);
  a023=(a023+a029);
  a029=(a058*a031);
  a023=(a023+a029);
  a011=(a023*a011);
  a052=(a052+a011);
  a017=(a045*a017);
  a019=(a028*a019);
  a017=(a017-a019);
  a035=(a046*a035);
  a017=(a017+a035);
  a031=(a015*a031);
  a017=(a017+a031);
  a030=(a058*a030);
  a017=(a017+a030);
  a071=(a017*a071);
  a052=(a052+a071);
  if (res[1]!=0) res[1][1]=a052;
  a032=(a032*a028);
  a001=(a001*a045);
  a032=(a032+a001);
  a013=(a013*a046);
  a032=(a032+a013);
  a102=(a102*a015);
  a032=(a032+a102);
  a107=(a107*a058);
  a032=(a032+a107);
  if (res[1]!=0) res[1][2]=a032;
  a005=(a005*a028);
  a027=(a027*a045);
  a005=(a005+a027);
  a025=(a025*a046);
  a005=(a005+a025);
  a023=(a023*a015);
  a005=(a005+a023);
  a017=(a017*a058);
  a005=(a005+a017);
  if (res[1]!=0) res[1][3]=a005;
  a005=(a069*a034);
  a017=(a079*a070);
  a005=(a005+a017);
  a017=(a093*a066);
  a005=(a005+a017);
  a017=(a099*a006);
  a005=(a005+a017);
  a017=(a005*a069);
  a060=(a016*a060);
  a057=(a055*a057);
  a060=(a060-a057);
  a009=(a062*a009);
  a060=(a060+a009);
  a075=(a003*a075);
  a060=(a060-a075);
  a074=(a063*a074);
  a060=(a060+a074);
  a074=(a069*a060);
  a075=(a079*a076);
  a074=(a074+a075);
  a075=(a093*a082);
  a074=(a074+a075);
  a075=(a099*a097);
  a074=(a074+a075);
  a075=(a074*a079);
  a017=(a017+a075);
  a075=(a016*a086);
  a009=(a055*a085);
  a075=(a075-a009);
  a009=(a062*a087);
  a075=(a075+a009);
  a089=(a003*a089);
  a075=(a075+a089);
  a090=(a063*a090);
  a075=(a075-a090);
  a090=(a069*a075);
  a085=(a018*a085);
  a086=(a000*a086);
  a085=(a085-a086);
  a087=(a033*a087);
  a085=(a085+a087);
  a087=(a079*a085);
  a090=(a090+a087);
  a087=(a093*a088);
  a090=(a090+a087);
  a087=(a099*a096);
  a090=(a090+a087);
  a087=(a090*a093);
  a017=(a017+a087);
  a016=(a016*a053);
  a055=(a055*a084);
  a016=(a016-a055);
  a062=(a062*a042);
  a016=(a016+a062);
  a003=(a003*a047);
  a016=(a016+a003);
  a063=(a063*a100);
  a016=(a016+a063);
  a063=(a069*a016);
  a018=(a018*a084);
  a000=(a000*a053);
  a018=(a018-a000);
  a033=(a033*a042);
  a018=(a018+a033);
  a033=(a079*a018);
  a063=(a063+a033);
  a081=(a081*a084);
  a004=(a004*a053);
  a081=(a081-a004);
  a068=(a068*a042);
  a081=(a081+a068);
  a059=(a059*a047);
  a081=(a081+a059);
  a059=(a093*a081);
  a063=(a063+a059);
  a059=(a099*a044);
  a063=(a063+a059);
  a059=(a063*a099);
  a017=(a017+a059);
  if (res[2]!=0) res[2][0]=a017;
  a034=(a067*a034);
  a070=(a036*a070);
  a034=(a034+a070);
  a066=(a038*a066);
  a034=(a034+a066);
  a006=(a094*a006);
  a034=(a034+a006);
  a006=(a034*a069);
  a060=(a067*a060);
  a076=(a036*a076);
  a060=(a060+a076);
  a082=(a038*a082);
  a060=(a060+a082);
  a097=(a094*a097);
  a060=(a060+a097);
  a079=(a060*a079);
  a006=(a006+a079);
  a075=(a067*a075);
  a085=(a036*a085);
  a075=(a075+a085);
  a088=(a038*a088);
  a075=(a075+a088);
  a096=(a094*a096);
  a075=(a075+a096);
  a093=(a075*a093);
  a006=(a006+a093);
  a016=(a067*a016);
  a018=(a036*a018);
  a016=(a016+a018);
  a081=(a038*a081);
  a016=(a016+a081);
  a044=(a094*a044);
  a016=(a016+a044);
  a099=(a016*a099);
  a006=(a006+a099);
  if (res[2]!=0) res[2][1]=a006;
  a005=(a005*a067);
  a074=(a074*a036);
  a005=(a005+a074);
  a090=(a090*a038);
  a005=(a005+a090);
  a063=(a063*a094);
  a005=(a005+a063);
  if (res[2]!=0) res[2][2]=a005;
  a034=(a034*a067);
  a060=(a060*a036);
  a034=(a034+a060);
  a075=(a075*a038);
  a034=(a034+a075);
  a016=(a016*a094);
  a034=(a034+a016);
  if (res[2]!=0) res[2][3]=a034;
  if (res[3]!=0) res[3][0]=a051;
  a049=(-a049);
  if (res[3]!=0) res[3][1]=a049;
  if (res[3]!=0) res[3][2]=a049;
  if (res[3]!=0) res[3][3]=a048;
  a069=(-a069);
  if (res[4]!=0) res[4][0]=a069;
  a067=(-a067);
  if (res[4]!=0) res[4][1]=a067;
  a078=(a078/a077);
  a002=casadi_fmin(a002,a078);
  a092=(a092/a091);
  a002=casadi_fmin(a002,a092);
  a010=(a010/a073);
  a002=casadi_fmin(a002,a010);
  if (res[5]!=0) res[5][0]=a002;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_metric_forms_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_metric_forms_n_in(void) { return 11;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_metric_forms_n_out(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na2_metric_forms_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_metric_forms_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    case 2: return "contact_link";
    case 3: return "side";
    case 4: return "object_mass";
    case 5: return "object_inertia";
    case 6: return "q_obj";
    case 7: return "rho";
    case 8: return "wheel_offset";
    case 9: return "free";
    case 10: return "regularization";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_metric_forms_name_out(casadi_int i) {
  switch (i) {
    case 0: return "omega_tau";
    case 1: return "xi_tau";
    case 2: return "lambda_form_tau";
    case 3: return "input_metric";
    case 4: return "contact_from_tau";
    case 5: return "pivot_ratio";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_metric_forms_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    case 6: return casadi_s2;
    case 7: return casadi_s4;
    case 8: return casadi_s2;
    case 9: return casadi_s5;
    case 10: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_metric_forms_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s6;
    case 1: return casadi_s6;
    case 2: return casadi_s6;
    case 3: return casadi_s6;
    case 4: return casadi_s7;
    case 5: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 11;
  if (sz_res) *sz_res = 6;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_metric_forms_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 11*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 6*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na2_batch_metric_forms(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[11];
  casadi_real* r[6];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 110);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 11; ++k) a[k] = 0;
  for (k = 0; k < 6; ++k) r[k] = 0;
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
    r[0] = res[0] + i * 4;
    r[1] = res[1] + i * 4;
    r[2] = res[2] + i * 4;
    r[3] = res[3] + i * 4;
    r[4] = res[4] + i * 2;
    r[5] = res[5] + i * 1;
    if (snakecg_na2_metric_forms(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
