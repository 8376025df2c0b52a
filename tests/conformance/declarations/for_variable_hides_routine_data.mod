MODULE for_variable_hides_routine_data
  ! Tests: the FOR loop variable also hides a routine data object of the same
  ! name, which keeps its value after the loop.
  PROC main()
    VAR num k := 42;
    VAR num sum := 0;
    FOR k FROM 1 TO 4 DO
      sum := sum + k;
    ENDFOR
    TPWrite "sum=" \Num:=sum;
    TPWrite "k=" \Num:=k;
  ENDPROC
ENDMODULE
