MODULE trap_sees_and_changes_globals
  ! Tests: a TRAP reads and writes module data; the interrupted routine sees
  ! the new values when it resumes, and its own routine data are untouched.
  VAR signaldo do1;
  VAR intnum ir1;
  VAR num shared := 1;
  PROC main()
    VAR num mine := 5;
    AliasIO "DO1", do1;
    CONNECT ir1 WITH onRise;
    ISignalDO do1, 1, ir1;
    SetDO do1, 1;
    TPWrite "shared=" \Num:=shared;
    TPWrite "mine=" \Num:=mine;
  ENDPROC
  TRAP onRise
    VAR num mine := 99;
    shared := shared * 10 + mine;
  ENDTRAP
ENDMODULE
