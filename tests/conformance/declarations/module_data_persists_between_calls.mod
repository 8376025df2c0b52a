MODULE module_data_persists
  ! Tests: module VAR data keep their value from one routine call to the next
  ! and are shared by all routines of the module.
  VAR num total := 0;
  PROC add(num v)
    total := total + v;
  ENDPROC
  PROC main()
    add 5;
    add 7;
    add -2;
    TPWrite "total=" \Num:=total;
  ENDPROC
ENDMODULE
