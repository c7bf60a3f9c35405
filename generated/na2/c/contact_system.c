/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_system() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 92aa81f73b9d7ff69afc31c561cda203208b6d2de4fc2c5b6871a20f60622a96
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

/* snakecg_na2_contact_system:(q[5],v[5],tau[2],q_obj[3],v_obj[3],f_obj[3],K[25],contact_link[3],side,object_mass,object_inertia,rho[2],wheel_offset[3])->(M[5x5],delassus[4x4],b[4],qdd_free[5],a_obj_free[3],qdd_from_lam[5x4],a_obj_from_lam[3x4],gap,s) */
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
  casadi_real a108, a109, a110, a111, a112, a113, a114;
  a000=arg[6]? arg[6][12] : 0;
  if (res[0]!=0) res[0][0]=a000;
  a001=0.;
  if (res[0]!=0) res[0][1]=a001;
  a002=arg[6]? arg[6][15] : 0;
  a003=arg[0]? arg[0][3] : 0;
  a004=arg[0]? arg[0][2] : 0;
  a003=(a003+a004);
  a005=arg[0]? arg[0][4] : 0;
  a005=(a003+a005);
  a006=sin(a005);
  a007=(a002*a006);
  a008=arg[6]? arg[6][14] : 0;
  a009=sin(a003);
  a010=(a008*a009);
  a010=(a007+a010);
  a011=arg[6]? arg[6][13] : 0;
  a012=sin(a004);
  a013=(a011*a012);
  a013=(a010+a013);
  a014=(-a013);
  if (res[0]!=0) res[0][2]=a014;
  a015=(-a010);
  if (res[0]!=0) res[0][3]=a015;
  a016=(-a007);
  if (res[0]!=0) res[0][4]=a016;
  if (res[0]!=0) res[0][5]=a001;
  if (res[0]!=0) res[0][6]=a000;
  a017=cos(a005);
  a002=(a002*a017);
  a018=cos(a003);
  a008=(a008*a018);
  a008=(a002+a008);
  a019=cos(a004);
  a011=(a011*a019);
  a011=(a008+a011);
  if (res[0]!=0) res[0][7]=a011;
  if (res[0]!=0) res[0][8]=a008;
  if (res[0]!=0) res[0][9]=a002;
  if (res[0]!=0) res[0][10]=a014;
  if (res[0]!=0) res[0][11]=a011;
  a014=(a019*a018);
  a020=(a012*a009);
  a014=(a014+a020);
  a020=arg[6]? arg[6][17] : 0;
  a014=(a014*a020);
  a020=(a018*a017);
  a021=(a009*a006);
  a020=(a020+a021);
  a021=arg[6]? arg[6][20] : 0;
  a020=(a020*a021);
  a021=arg[6]? arg[6][23] : 0;
  a021=(a020+a021);
  a022=(a014+a021);
  a023=(a019*a017);
  a024=(a012*a006);
  a023=(a023+a024);
  a024=arg[6]? arg[6][18] : 0;
  a023=(a023*a024);
  a024=arg[6]? arg[6][24] : 0;
  a020=(a020+a024);
  a025=(a023+a020);
  a022=(a022+a025);
  a014=(a014+a023);
  a023=arg[6]? arg[6][22] : 0;
  a023=(a014+a023);
  a022=(a022+a023);
  if (res[0]!=0) res[0][12]=a022;
  a021=(a021+a020);
  a014=(a021+a014);
  if (res[0]!=0) res[0][13]=a014;
  if (res[0]!=0) res[0][14]=a025;
  if (res[0]!=0) res[0][15]=a015;
  if (res[0]!=0) res[0][16]=a008;
  if (res[0]!=0) res[0][17]=a014;
  if (res[0]!=0) res[0][18]=a021;
  if (res[0]!=0) res[0][19]=a020;
  if (res[0]!=0) res[0][20]=a016;
  if (res[0]!=0) res[0][21]=a002;
  if (res[0]!=0) res[0][22]=a025;
  if (res[0]!=0) res[0][23]=a020;
  if (res[0]!=0) res[0][24]=a024;
  a016=arg[7]? arg[7][0] : 0;
  a004=(a004*a016);
  a015=arg[7]? arg[7][1] : 0;
  a003=(a003*a015);
  a004=(a004+a003);
  a003=arg[7]? arg[7][2] : 0;
  a005=(a005*a003);
  a004=(a004+a005);
  a005=sin(a004);
  a023=arg[8]? arg[8][0] : 0;
  a026=(a005*a023);
  a027=(a016+a015);
  a027=(a027+a003);
  a028=(a026*a027);
  a029=(a028/a000);
  a013=(a013/a000);
  a030=arg[0]? arg[0][1] : 0;
  a031=arg[6]? arg[6][3] : 0;
  a032=arg[6]? arg[6][9] : 0;
  a031=(a031-a032);
  a033=(a031*a012);
  a034=(a030+a033);
  a035=arg[6]? arg[6][10] : 0;
  a036=(a009*a035);
  a037=(a034+a036);
  a038=(a030-a037);
  a039=(a015*a038);
  a040=arg[6]? arg[6][4] : 0;
  a040=(a040-a035);
  a041=(a040*a009);
  a042=(a037+a041);
  a043=arg[6]? arg[6][11] : 0;
  a044=(a006*a043);
  a042=(a042+a044);
  a045=(a030-a042);
  a046=(a003*a045);
  a039=(a039+a046);
  a046=(a026*a039);
  a004=cos(a004);
  a047=(a004*a023);
  a048=arg[0]? arg[0][0] : 0;
  a049=(a019*a031);
  a050=(a048+a049);
  a051=(a018*a035);
  a052=(a050+a051);
  a053=(a052-a048);
  a054=(a015*a053);
  a055=(a018*a040);
  a056=(a052+a055);
  a057=(a017*a043);
  a056=(a056+a057);
  a058=(a056-a048);
  a059=(a003*a058);
  a054=(a054+a059);
  a059=(a047*a054);
  a046=(a046-a059);
  a032=(a032*a016);
  a059=(a035*a015);
  a032=(a032+a059);
  a059=(a043*a003);
  a032=(a032+a059);
  a059=(a023*a032);
  a060=arg[3]? arg[3][2] : 0;
  a061=cos(a060);
  a062=arg[11]? arg[11][1] : 0;
  a063=(a061*a062);
  a060=sin(a060);
  a064=arg[11]? arg[11][0] : 0;
  a065=(a060*a064);
  a063=(a063+a065);
  a065=arg[3]? arg[3][1] : 0;
  a065=(a063+a065);
  a066=(a005*a032);
  a065=(a065+a066);
  a066=(a030*a016);
  a037=(a037*a015);
  a066=(a066+a037);
  a037=(a042*a003);
  a066=(a066+a037);
  a065=(a065-a066);
  a066=(a026*a065);
  a059=(a059-a066);
  a061=(a061*a064);
  a060=(a060*a062);
  a061=(a061-a060);
  a060=arg[3]? arg[3][0] : 0;
  a060=(a061+a060);
  a032=(a004*a032);
  a060=(a060+a032);
  a016=(a048*a016);
  a052=(a052*a015);
  a016=(a016+a052);
  a052=(a056*a003);
  a016=(a016+a052);
  a060=(a060-a016);
  a016=(a047*a060);
  a059=(a059-a016);
  a016=(a059*a027);
  a046=(a046+a016);
  a016=(a013*a028);
  a016=(a046+a016);
  a011=(a011/a000);
  a052=(a047*a027);
  a032=(a011*a052);
  a016=(a016+a032);
  a032=casadi_sq(a013);
  a032=(a032*a000);
  a022=(a022-a032);
  a032=casadi_sq(a011);
  a032=(a032*a000);
  a022=(a022-a032);
  a032=(a016/a022);
  a010=(a010/a000);
  a062=(a010*a013);
  a062=(a062*a000);
  a014=(a014-a062);
  a008=(a008/a000);
  a062=(a008*a011);
  a062=(a062*a000);
  a014=(a014-a062);
  a014=(a014/a022);
  a034=(a034-a042);
  a042=(a003*a034);
  a062=(a015*a036);
  a042=(a042-a062);
  a062=(a026*a042);
  a064=(a015*a051);
  a056=(a056-a050);
  a050=(a003*a056);
  a064=(a064+a050);
  a050=(a047*a064);
  a062=(a062-a050);
  a050=(a015+a003);
  a066=(a059*a050);
  a062=(a062+a066);
  a066=(a010*a028);
  a066=(a062+a066);
  a037=(a008*a052);
  a066=(a066+a037);
  a037=(a014*a016);
  a066=(a066-a037);
  a037=casadi_sq(a010);
  a037=(a037*a000);
  a021=(a021-a037);
  a037=casadi_sq(a008);
  a037=(a037*a000);
  a021=(a021-a037);
  a037=casadi_sq(a014);
  a037=(a037*a022);
  a021=(a021-a037);
  a037=(a066/a021);
  a007=(a007/a000);
  a067=(a007*a010);
  a067=(a067*a000);
  a020=(a020-a067);
  a002=(a002/a000);
  a067=(a002*a008);
  a067=(a067*a000);
  a020=(a020-a067);
  a067=(a007*a013);
  a067=(a067*a000);
  a025=(a025-a067);
  a067=(a002*a011);
  a067=(a067*a000);
  a025=(a025-a067);
  a025=(a025/a022);
  a067=(a025*a014);
  a067=(a067*a022);
  a020=(a020-a067);
  a020=(a020/a021);
  a059=(a059*a003);
  a067=(a003*a044);
  a068=(a026*a067);
  a069=(a003*a057);
  a070=(a047*a069);
  a068=(a068+a070);
  a059=(a059-a068);
  a068=(a007*a028);
  a068=(a059+a068);
  a070=(a002*a052);
  a068=(a068+a070);
  a016=(a025*a016);
  a068=(a068-a016);
  a066=(a020*a066);
  a068=(a068-a066);
  a066=casadi_sq(a007);
  a066=(a066*a000);
  a024=(a024-a066);
  a066=casadi_sq(a002);
  a066=(a066*a000);
  a024=(a024-a066);
  a066=casadi_sq(a025);
  a066=(a066*a022);
  a024=(a024-a066);
  a066=casadi_sq(a020);
  a066=(a066*a021);
  a024=(a024-a066);
  a068=(a068/a024);
  a066=(a020*a068);
  a037=(a037-a066);
  a066=(a014*a037);
  a032=(a032-a066);
  a066=(a025*a068);
  a032=(a032-a066);
  a066=(a013*a032);
  a029=(a029+a066);
  a066=(a010*a037);
  a029=(a029+a066);
  a066=(a007*a068);
  a029=(a029+a066);
  a066=(a028*a029);
  a016=(a052/a000);
  a070=(a011*a032);
  a016=(a016+a070);
  a070=(a008*a037);
  a016=(a016+a070);
  a070=(a002*a068);
  a016=(a016+a070);
  a070=(a052*a016);
  a066=(a066+a070);
  a070=(a046*a032);
  a066=(a066+a070);
  a070=(a062*a037);
  a066=(a066+a070);
  a070=(a059*a068);
  a066=(a066+a070);
  a070=arg[9]? arg[9][0] : 0;
  a071=(a026/a070);
  a072=(a026*a071);
  a073=(a047/a070);
  a074=(a047*a073);
  a072=(a072+a074);
  a074=(a004*a061);
  a074=(a074*a023);
  a075=(a026*a063);
  a074=(a074+a075);
  a075=arg[10]? arg[10][0] : 0;
  a076=(a074/a075);
  a077=(a074*a076);
  a072=(a072+a077);
  a066=(a066+a072);
  if (res[1]!=0) res[1][0]=a066;
  a066=arg[12]? arg[12][0] : 0;
  a072=(a066*a032);
  a077=(a012*a029);
  a078=(a019*a016);
  a077=(a077+a078);
  a072=(a072-a077);
  if (res[1]!=0) res[1][1]=a072;
  a072=(a018*a053);
  a077=(a009*a038);
  a072=(a072-a077);
  a077=arg[12]? arg[12][1] : 0;
  a072=(a072+a077);
  a078=(a072*a032);
  a079=(a009*a029);
  a080=(a018*a016);
  a079=(a079+a080);
  a078=(a078-a079);
  a079=(a009*a036);
  a080=(a018*a051);
  a079=(a079+a080);
  a079=(a079+a077);
  a077=(a079*a037);
  a078=(a078+a077);
  if (res[1]!=0) res[1][2]=a078;
  a078=(a017*a058);
  a077=(a006*a045);
  a078=(a078-a077);
  a077=arg[12]? arg[12][2] : 0;
  a078=(a078+a077);
  a080=(a078*a032);
  a081=(a006*a029);
  a082=(a017*a016);
  a081=(a081+a082);
  a080=(a080-a081);
  a081=(a017*a056);
  a082=(a006*a034);
  a081=(a081-a082);
  a081=(a081+a077);
  a082=(a081*a037);
  a080=(a080+a082);
  a082=(a006*a044);
  a083=(a017*a057);
  a082=(a082+a083);
  a082=(a082+a077);
  a077=(a082*a068);
  a080=(a080+a077);
  if (res[1]!=0) res[1][3]=a080;
  a080=(a013*a012);
  a080=(a066-a080);
  a077=(a011*a019);
  a080=(a080-a077);
  a077=(a080/a022);
  a083=(a010*a012);
  a084=(a008*a019);
  a083=(a083+a084);
  a084=(a014*a080);
  a083=(a083+a084);
  a084=(a083/a021);
  a083=(a020*a083);
  a085=(a007*a012);
  a086=(a002*a019);
  a085=(a085+a086);
  a080=(a025*a080);
  a085=(a085+a080);
  a083=(a083-a085);
  a083=(a083/a024);
  a085=(a020*a083);
  a084=(a084+a085);
  a085=(a014*a084);
  a077=(a077+a085);
  a085=(a025*a083);
  a077=(a077-a085);
  a085=(a013*a077);
  a080=(a012/a000);
  a085=(a085-a080);
  a080=(a010*a084);
  a085=(a085-a080);
  a080=(a007*a083);
  a085=(a085+a080);
  a080=(a028*a085);
  a086=(a019/a000);
  a087=(a011*a077);
  a086=(a086-a087);
  a087=(a008*a084);
  a086=(a086+a087);
  a087=(a002*a083);
  a086=(a086-a087);
  a087=(a052*a086);
  a080=(a080-a087);
  a087=(a046*a077);
  a080=(a080+a087);
  a087=(a062*a084);
  a080=(a080-a087);
  a087=(a059*a083);
  a080=(a080+a087);
  if (res[1]!=0) res[1][4]=a080;
  a080=(a019*a086);
  a087=(a012*a085);
  a080=(a080-a087);
  a087=(a066*a077);
  a080=(a080+a087);
  if (res[1]!=0) res[1][5]=a080;
  a080=(a018*a086);
  a087=(a009*a085);
  a080=(a080-a087);
  a087=(a072*a077);
  a080=(a080+a087);
  a087=(a079*a084);
  a080=(a080-a087);
  if (res[1]!=0) res[1][6]=a080;
  a080=(a017*a086);
  a087=(a006*a085);
  a080=(a080-a087);
  a087=(a078*a077);
  a080=(a080+a087);
  a087=(a081*a084);
  a080=(a080-a087);
  a087=(a082*a083);
  a080=(a080+a087);
  if (res[1]!=0) res[1][7]=a080;
  a080=(a013*a009);
  a080=(a072-a080);
  a087=(a011*a018);
  a080=(a080-a087);
  a087=(a080/a022);
  a088=(a010*a009);
  a088=(a079-a088);
  a089=(a008*a018);
  a088=(a088-a089);
  a089=(a014*a080);
  a088=(a088-a089);
  a089=(a088/a021);
  a090=(a007*a009);
  a091=(a002*a018);
  a090=(a090+a091);
  a080=(a025*a080);
  a090=(a090+a080);
  a088=(a020*a088);
  a090=(a090+a088);
  a090=(a090/a024);
  a088=(a020*a090);
  a089=(a089+a088);
  a088=(a014*a089);
  a087=(a087-a088);
  a088=(a025*a090);
  a087=(a087+a088);
  a088=(a013*a087);
  a080=(a009/a000);
  a088=(a088-a080);
  a080=(a010*a089);
  a088=(a088+a080);
  a080=(a007*a090);
  a088=(a088-a080);
  a080=(a028*a088);
  a091=(a018/a000);
  a092=(a011*a087);
  a091=(a091-a092);
  a092=(a008*a089);
  a091=(a091-a092);
  a092=(a002*a090);
  a091=(a091+a092);
  a092=(a052*a091);
  a080=(a080-a092);
  a092=(a046*a087);
  a080=(a080+a092);
  a092=(a062*a089);
  a080=(a080+a092);
  a092=(a059*a090);
  a080=(a080-a092);
  if (res[1]!=0) res[1][8]=a080;
  a080=(a019*a091);
  a092=(a012*a088);
  a080=(a080-a092);
  a092=(a066*a087);
  a080=(a080+a092);
  if (res[1]!=0) res[1][9]=a080;
  a080=(a018*a091);
  a092=(a009*a088);
  a080=(a080-a092);
  a092=(a072*a087);
  a080=(a080+a092);
  a092=(a079*a089);
  a080=(a080+a092);
  if (res[1]!=0) res[1][10]=a080;
  a080=(a017*a091);
  a092=(a006*a088);
  a080=(a080-a092);
  a092=(a078*a087);
  a080=(a080+a092);
  a092=(a081*a089);
  a080=(a080+a092);
  a092=(a082*a090);
  a080=(a080-a092);
  if (res[1]!=0) res[1][11]=a080;
  a080=(a013*a006);
  a080=(a078-a080);
  a092=(a011*a017);
  a080=(a080-a092);
  a092=(a080/a022);
  a093=(a010*a006);
  a093=(a081-a093);
  a094=(a008*a017);
  a093=(a093-a094);
  a094=(a014*a080);
  a093=(a093-a094);
  a094=(a093/a021);
  a095=(a007*a006);
  a095=(a082-a095);
  a096=(a002*a017);
  a095=(a095-a096);
  a080=(a025*a080);
  a095=(a095-a080);
  a093=(a020*a093);
  a095=(a095-a093);
  a095=(a095/a024);
  a093=(a020*a095);
  a094=(a094-a093);
  a093=(a014*a094);
  a092=(a092-a093);
  a093=(a025*a095);
  a092=(a092-a093);
  a093=(a013*a092);
  a080=(a006/a000);
  a093=(a093-a080);
  a080=(a010*a094);
  a093=(a093+a080);
  a080=(a007*a095);
  a093=(a093+a080);
  a080=(a028*a093);
  a096=(a017/a000);
  a097=(a011*a092);
  a096=(a096-a097);
  a097=(a008*a094);
  a096=(a096-a097);
  a097=(a002*a095);
  a096=(a096-a097);
  a097=(a052*a096);
  a080=(a080-a097);
  a097=(a046*a092);
  a080=(a080+a097);
  a097=(a062*a094);
  a080=(a080+a097);
  a097=(a059*a095);
  a080=(a080+a097);
  if (res[1]!=0) res[1][12]=a080;
  a080=(a019*a096);
  a097=(a012*a093);
  a080=(a080-a097);
  a097=(a066*a092);
  a080=(a080+a097);
  if (res[1]!=0) res[1][13]=a080;
  a080=(a018*a096);
  a097=(a009*a093);
  a080=(a080-a097);
  a097=(a072*a092);
  a080=(a080+a097);
  a097=(a079*a094);
  a080=(a080+a097);
  if (res[1]!=0) res[1][14]=a080;
  a080=(a017*a096);
  a097=(a006*a093);
  a080=(a080-a097);
  a097=(a078*a092);
  a080=(a080+a097);
  a097=(a081*a094);
  a080=(a080+a097);
  a097=(a082*a095);
  a080=(a080+a097);
  if (res[1]!=0) res[1][15]=a080;
  a080=arg[1]? arg[1][2] : 0;
  a097=casadi_sq(a080);
  a098=(a097*a049);
  a099=arg[1]? arg[1][3] : 0;
  a100=(a099+a080);
  a101=casadi_sq(a100);
  a102=(a101*a051);
  a098=(a098+a102);
  a102=arg[6]? arg[6][1] : 0;
  a103=(a098*a102);
  a104=arg[1]? arg[1][4] : 0;
  a100=(a100+a104);
  a100=casadi_sq(a100);
  a105=(a057*a100);
  a098=(a098+a105);
  a105=(a101*a055);
  a098=(a098+a105);
  a105=arg[6]? arg[6][2] : 0;
  a098=(a098*a105);
  a106=(a103+a098);
  a107=(a106/a000);
  a108=(a013*a106);
  a109=(a033+a030);
  a110=(a036+a109);
  a111=(a041+a110);
  a112=(a044+a111);
  a112=(a098*a112);
  a033=(a097*a033);
  a113=(a101*a036);
  a033=(a033+a113);
  a041=(a041*a101);
  a041=(a033+a041);
  a113=(a044*a100);
  a041=(a041+a113);
  a049=(a049+a048);
  a113=(a051+a049);
  a055=(a055+a113);
  a114=(a057+a055);
  a114=(a041*a114);
  a114=(a114*a105);
  a112=(a112-a114);
  a033=(a033*a102);
  a113=(a033*a113);
  a113=(a112-a113);
  a103=(a103*a110);
  a113=(a113+a103);
  a030=(a106*a030);
  a030=(a113-a030);
  a041=(a041*a105);
  a033=(a033+a041);
  a048=(a033*a048);
  a030=(a030+a048);
  a108=(a108-a030);
  a030=(a011*a033);
  a108=(a108-a030);
  a022=(a108/a022);
  a030=arg[2]? arg[2][0] : 0;
  a109=(a106*a109);
  a113=(a113-a109);
  a049=(a033*a049);
  a113=(a113+a049);
  a030=(a030-a113);
  a113=(a010*a106);
  a030=(a030+a113);
  a113=(a008*a033);
  a030=(a030-a113);
  a113=(a014*a108);
  a030=(a030-a113);
  a021=(a030/a021);
  a113=arg[2]? arg[2][1] : 0;
  a098=(a098*a111);
  a112=(a112-a098);
  a041=(a041*a055);
  a112=(a112+a041);
  a113=(a113-a112);
  a106=(a007*a106);
  a113=(a113+a106);
  a106=(a002*a033);
  a113=(a113-a106);
  a108=(a025*a108);
  a113=(a113-a108);
  a030=(a020*a030);
  a113=(a113-a030);
  a113=(a113/a024);
  a020=(a020*a113);
  a021=(a021-a020);
  a014=(a014*a021);
  a022=(a022-a014);
  a025=(a025*a113);
  a022=(a022-a025);
  a013=(a013*a022);
  a107=(a107+a013);
  a010=(a010*a021);
  a107=(a107+a010);
  a007=(a007*a113);
  a107=(a107+a007);
  a028=(a028*a107);
  a033=(a033/a000);
  a011=(a011*a022);
  a033=(a033-a011);
  a008=(a008*a021);
  a033=(a033-a008);
  a002=(a002*a113);
  a033=(a033-a002);
  a052=(a052*a033);
  a028=(a028-a052);
  a046=(a046*a022);
  a028=(a028+a046);
  a062=(a062*a021);
  a028=(a028+a062);
  a059=(a059*a113);
  a028=(a028+a059);
  a059=arg[5]? arg[5][1] : 0;
  a059=(a059/a070);
  a062=(a047*a059);
  a046=arg[5]? arg[5][0] : 0;
  a046=(a046/a070);
  a070=(a026*a046);
  a062=(a062-a070);
  a070=arg[5]? arg[5][2] : 0;
  a070=(a070/a075);
  a074=(a074*a070);
  a062=(a062+a074);
  a028=(a028+a062);
  a062=arg[1]? arg[1][0] : 0;
  a074=(a027*a062);
  a039=(a039*a080);
  a074=(a074+a039);
  a042=(a042*a099);
  a074=(a074+a042);
  a067=(a067*a104);
  a074=(a074-a067);
  a074=(a047*a074);
  a067=(a027*a080);
  a050=(a050*a099);
  a067=(a067+a050);
  a050=(a003*a104);
  a067=(a067+a050);
  a050=(a074*a067);
  a097=(a097*a031);
  a031=(a019*a097);
  a035=(a101*a035);
  a042=(a018*a035);
  a031=(a031+a042);
  a042=(a031*a015);
  a101=(a101*a040);
  a040=(a018*a101);
  a040=(a031+a040);
  a043=(a043*a100);
  a100=(a017*a043);
  a040=(a040+a100);
  a100=(a040*a003);
  a042=(a042+a100);
  a042=(a026*a042);
  a050=(a050-a042);
  a042=arg[1]? arg[1][1] : 0;
  a027=(a027*a042);
  a054=(a054*a080);
  a027=(a027+a054);
  a064=(a064*a099);
  a027=(a027+a064);
  a069=(a069*a104);
  a027=(a027+a069);
  a027=(a026*a027);
  a069=(a027*a067);
  a050=(a050+a069);
  a074=(a074+a027);
  a063=(a063*a047);
  a061=(a026*a061);
  a027=(a063-a061);
  a069=arg[4]? arg[4][2] : 0;
  a064=(a027*a069);
  a074=(a074+a064);
  a064=arg[4]? arg[4][0] : 0;
  a064=(a047*a064);
  a074=(a074-a064);
  a054=arg[4]? arg[4][1] : 0;
  a026=(a026*a054);
  a074=(a074-a026);
  a054=(a065*a047);
  a100=(a005*a060);
  a100=(a100*a023);
  a054=(a054-a100);
  a100=(a054*a067);
  a074=(a074-a100);
  a074=(a067*a074);
  a050=(a050+a074);
  a027=(a027*a067);
  a061=(a061-a063);
  a061=(a069*a061);
  a027=(a027+a061);
  a069=(a069*a027);
  a050=(a050+a069);
  a064=(a064*a067);
  a050=(a050-a064);
  a026=(a026*a067);
  a050=(a050-a026);
  a097=(a097*a012);
  a035=(a035*a009);
  a097=(a097+a035);
  a015=(a097*a015);
  a101=(a101*a009);
  a101=(a097+a101);
  a043=(a043*a006);
  a101=(a101+a043);
  a003=(a101*a003);
  a015=(a015+a003);
  a047=(a047*a015);
  a050=(a050+a047);
  a028=(a028+a050);
  if (res[2]!=0) res[2][0]=a028;
  a028=(a019*a033);
  a050=(a012*a107);
  a028=(a028-a050);
  a066=(a066*a022);
  a028=(a028+a066);
  a012=(a012*a042);
  a012=(a012*a080);
  a019=(a019*a062);
  a019=(a019*a080);
  a012=(a012+a019);
  a028=(a028-a012);
  if (res[2]!=0) res[2][1]=a028;
  a028=(a018*a033);
  a012=(a009*a107);
  a028=(a028-a012);
  a072=(a072*a022);
  a028=(a028+a072);
  a079=(a079*a021);
  a028=(a028+a079);
  a031=(a009*a031);
  a097=(a018*a097);
  a031=(a031-a097);
  a053=(a053*a080);
  a053=(a042+a053);
  a051=(a051*a099);
  a053=(a053+a051);
  a009=(a009*a053);
  a053=(a080+a099);
  a009=(a009*a053);
  a031=(a031-a009);
  a038=(a038*a080);
  a038=(a062+a038);
  a036=(a036*a099);
  a038=(a038-a036);
  a018=(a018*a038);
  a018=(a018*a053);
  a031=(a031-a018);
  a028=(a028+a031);
  if (res[2]!=0) res[2][2]=a028;
  a028=(a017*a033);
  a031=(a006*a107);
  a028=(a028-a031);
  a078=(a078*a022);
  a028=(a028+a078);
  a081=(a081*a021);
  a028=(a028+a081);
  a082=(a082*a113);
  a028=(a028+a082);
  a040=(a006*a040);
  a101=(a017*a101);
  a040=(a040-a101);
  a058=(a058*a080);
  a042=(a042+a058);
  a056=(a056*a099);
  a042=(a042+a056);
  a057=(a057*a104);
  a042=(a042+a057);
  a006=(a006*a042);
  a053=(a053+a104);
  a006=(a006*a053);
  a040=(a040-a006);
  a045=(a045*a080);
  a062=(a062+a045);
  a034=(a034*a099);
  a062=(a062+a034);
  a044=(a044*a104);
  a062=(a062-a044);
  a017=(a017*a062);
  a017=(a017*a053);
  a040=(a040-a017);
  a028=(a028+a040);
  if (res[2]!=0) res[2][3]=a028;
  if (res[3]!=0) res[3][0]=a107;
  if (res[3]!=0) res[3][1]=a033;
  if (res[3]!=0) res[3][2]=a022;
  if (res[3]!=0) res[3][3]=a021;
  if (res[3]!=0) res[3][4]=a113;
  if (res[4]!=0) res[4][0]=a046;
  if (res[4]!=0) res[4][1]=a059;
  if (res[4]!=0) res[4][2]=a070;
  if (res[5]!=0) res[5][0]=a029;
  a016=(-a016);
  if (res[5]!=0) res[5][1]=a016;
  if (res[5]!=0) res[5][2]=a032;
  if (res[5]!=0) res[5][3]=a037;
  if (res[5]!=0) res[5][4]=a068;
  if (res[5]!=0) res[5][5]=a085;
  if (res[5]!=0) res[5][6]=a086;
  if (res[5]!=0) res[5][7]=a077;
  a084=(-a084);
  if (res[5]!=0) res[5][8]=a084;
  if (res[5]!=0) res[5][9]=a083;
  if (res[5]!=0) res[5][10]=a088;
  if (res[5]!=0) res[5][11]=a091;
  if (res[5]!=0) res[5][12]=a087;
  if (res[5]!=0) res[5][13]=a089;
  a090=(-a090);
  if (res[5]!=0) res[5][14]=a090;
  if (res[5]!=0) res[5][15]=a093;
  if (res[5]!=0) res[5][16]=a096;
  if (res[5]!=0) res[5][17]=a092;
  if (res[5]!=0) res[5][18]=a094;
  if (res[5]!=0) res[5][19]=a095;
  a071=(-a071);
  if (res[6]!=0) res[6][0]=a071;
  if (res[6]!=0) res[6][1]=a073;
  if (res[6]!=0) res[6][2]=a076;
  if (res[6]!=0) res[6][3]=a001;
  if (res[6]!=0) res[6][4]=a001;
  if (res[6]!=0) res[6][5]=a001;
  if (res[6]!=0) res[6][6]=a001;
  if (res[6]!=0) res[6][7]=a001;
  if (res[6]!=0) res[6][8]=a001;
  if (res[6]!=0) res[6][9]=a001;
  if (res[6]!=0) res[6][10]=a001;
  if (res[6]!=0) res[6][11]=a001;
  if (res[7]!=0) res[7][0]=a054;
  a005=(a005*a065);
  a004=(a004*a060);
  a005=(a005+a004);
  if (res[8]!=0) res[8][0]=a005;
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

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_contact_system_n_in(void) { return 13;}

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
  if (sz_arg) *sz_arg = 13;
  if (sz_res) *sz_res = 9;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_contact_system_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13*sizeof(const casadi_real*);
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
  const casadi_real* a[13];
  casadi_real* r[9];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 116);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 13; ++k) a[k] = 0;
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
