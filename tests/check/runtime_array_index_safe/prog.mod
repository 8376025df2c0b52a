MODULE RuntimeArrayIndexSafe
    ! The index is DInput + 1: 1 or 2, always inside the array.
    VAR num slots{2} := [10, 20];
    VAR num picked := 0;

    PROC main()
        WHILE TRUE DO
            picked := slots{DInput(di_slot) + 1};
        ENDWHILE
    ENDPROC
ENDMODULE
