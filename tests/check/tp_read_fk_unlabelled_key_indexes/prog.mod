MODULE TpReadFkTrueDefect
    ! A real defect stays found: key 3 has a label, the array has two elements.
    CONST string names{2} := ["Pick", "Place"];
    VAR num key := 0;
    VAR string chosen := "";

    PROC main()
        TPReadFK key, "Program?", "Pick", "Place", "Service", stEmpty, stEmpty;
        chosen := names{key};
    ENDPROC
ENDMODULE
