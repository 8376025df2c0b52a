MODULE routine_data_hides_module_data
  ! Tests: a routine data object hides a module data object of the same name
  ! inside that routine only; writing it leaves the module one unchanged.
  VAR num x := 1;
  PROC inner()
    VAR num x := 5;
    x := x + 1;
    TPWrite "inner x=" \Num:=x;
  ENDPROC
  PROC main()
    inner;
    TPWrite "module x=" \Num:=x;
  ENDPROC
ENDMODULE
