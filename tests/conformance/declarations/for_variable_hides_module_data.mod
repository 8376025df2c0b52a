MODULE for_variable_hides_module_data
  ! Tests: the FOR loop variable is a new num local to the loop that hides a
  ! module variable of the same name; after the loop the module one is
  ! unchanged.
  VAR num i := 100;
  PROC main()
    FOR i FROM 1 TO 3 DO
      TPWrite "loop i=" \Num:=i;
    ENDFOR
    TPWrite "after i=" \Num:=i;
  ENDPROC
ENDMODULE
