MODULE changer
  ! toolslot is a tool changer's number type, declared by an add-in module that is not
  ! given: its data are assigned and compared as numbers and index an array
  VAR num wear{3} := [0, 0, 0];

  PROC swap(toolslot wanted)
    VAR toolslot current;
    current := Trunc(wear{1});
    IF current <> wanted AND wanted > 0 THEN
      wear{wanted} := wear{wanted} + 1;
    ENDIF
  ENDPROC

  PROC main()
    swap 2;
    swap 3;
  ENDPROC
ENDMODULE
