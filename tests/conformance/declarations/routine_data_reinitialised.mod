MODULE routine_data_reinitialised
  ! Tests: routine data are initialised on every call (no static locals),
  ! while module data keep their value between calls.
  VAR num calls := 0;
  PROC count()
    VAR num c := 10;
    c := c + 1;
    calls := calls + 1;
    TPWrite "c=" \Num:=c;
  ENDPROC
  PROC main()
    count;
    count;
    count;
    TPWrite "calls=" \Num:=calls;
  ENDPROC
ENDMODULE
