MODULE duplicate_routine_data
  ! Tests: a routine data object with the same name as a parameter of the
  ! same routine is a duplicate (names are unique within one routine,
  ! RMC204).
  PROC show(num v)
    VAR num v;  ! <-- error
    TPWrite "v=" \Num:=v;
  ENDPROC
  PROC main()
    show 1;
  ENDPROC
ENDMODULE
