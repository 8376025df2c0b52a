MODULE placeholder_clauses
  ! Tests: placeholders for declarations (<DDN>, <RDN>) declare nothing and load; an <EIT>
  ! (ELSEIF clause) is reached only when the conditions before it are false, a <CSE> (CASE
  ! clause) only when no CASE before it matched; reaching one raises ERR_EXECPHR (RAPID kernel
  ! reference, "Placeholders").
  <DDN>
  <RDN>
  VAR num x := 1;
  PROC main()
    <DDN>
    IF x = 1 THEN
      TPWrite "one";
    <EIT>
    ELSE
      TPWrite "else";
    ENDIF
    x := 2;
    TEST x
    CASE 2:
      TPWrite "two";
    <CSE>
    DEFAULT:
      TPWrite "default";
    ENDTEST
    x := 5;
    TPWrite "now 5";
    TEST x
    CASE 2:
      TPWrite "two";
    <CSE>
    ENDTEST
    TPWrite "not reached";
  ENDPROC
ENDMODULE
