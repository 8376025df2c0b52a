MODULE TpReadFkLabelled
    ! Issue 19: a menu of three labelled keys indexes an array of three programs. Keys 4
    ! and 5 have no label (stEmpty), so the FlexPendant does not offer them: the index
    ! stays within 1..3 and no run-time error is reachable.
    CONST string names{3} := ["Pick", "Place", "Home"];
    VAR num key := 0;
    VAR string chosen := "";

    PROC main()
        WHILE TRUE DO
            TPReadFK key, "Program?", "Pick", "Place", "Home", stEmpty, "";
            chosen := names{key};
        ENDWHILE
    ENDPROC
ENDMODULE
