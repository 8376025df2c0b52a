MODULE not_inside_and_chain
  ! Tests: project decision (reference 2.7): NOT may start any operand and
  ! extends to the end of the enclosing expression, so a AND NOT b AND c
  ! means a AND NOT (b AND c). With a=TRUE, b=TRUE, c=FALSE that is TRUE,
  ! while a AND (NOT b) AND c would be FALSE. This is the reading of the
  ! K-RAPID sorting program's flag_2 := c_in=0 AND NOT s1=1 AND s2=1.
  PROC main()
    VAR bool a := TRUE;
    VAR bool b := TRUE;
    VAR bool c := FALSE;
    VAR num c_in := 0;
    VAR num s1 := 1;
    VAR num s2 := 0;
    TPWrite "a AND NOT b AND c: " \Bool:=a AND NOT b AND c;
    TPWrite "flag_2: " \Bool:=c_in = 0 AND NOT s1 = 1 AND s2 = 1;
  ENDPROC
ENDMODULE
