MODULE isignaldo_single
  ! Tests: ISignalDO \Single fires only for the first matching edge; later
  ! edges run no trap.
  VAR signaldo do1;
  VAR intnum ir1;
  VAR num count := 0;
  PROC main()
    AliasIO "DO1", do1;
    CONNECT ir1 WITH onRise;
    ISignalDO \Single, do1, 1, ir1;
    SetDO do1, 1;
    SetDO do1, 0;
    SetDO do1, 1;
    TPWrite "count=" \Num:=count;
  ENDPROC
  TRAP onRise
    count := count + 1;
  ENDTRAP
ENDMODULE
