MODULE Receiver
    ! Written for the test (issue 28): announces the recipe the cell then clears.
    PERS bool bRecipeReady := FALSE;

    PROC main()
        WaitDI diRecipe, 1;
        bRecipeReady := TRUE;
    ENDPROC
ENDMODULE
