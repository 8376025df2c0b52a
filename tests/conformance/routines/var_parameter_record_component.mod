MODULE var_parameter_record_component
  ! Tests: a record component, and a component of an array element, may be
  ! passed to VAR/INOUT parameters by reference.
  VAR pos track{2};
  PROC setTo(VAR num v, num value)
    v := value;
  ENDPROC
  PROC main()
    VAR pos p := [1, 2, 3];
    setTo p.y, 20;
    setTo track{2}.z, 7;
    TPWrite "p=" \Pos:=p;
    TPWrite "track{2}=" \Pos:=track{2};
  ENDPROC
ENDMODULE
