MODULE DefectIndexNeverSet
    ! Issue 19, a true defect that must stay found: the operator's choice sets the slot
    ! in two branches, the third leaves it 0, and slots{0} is out of bounds.
    VAR num slots{3} := [10, 20, 30];
    VAR num slot := 0;
    VAR num key := 0;
    VAR num target := 0;

    PROC main()
        TPReadFK key, "Slot?", "Left", "Right", "Skip", stEmpty, stEmpty;
        IF key = 1 THEN
            slot := 1;
        ELSEIF key = 2 THEN
            slot := 3;
        ENDIF
        target := slots{slot};
    ENDPROC
ENDMODULE
