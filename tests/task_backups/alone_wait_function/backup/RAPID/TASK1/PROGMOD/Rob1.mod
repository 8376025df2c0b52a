MODULE Rob1
    ! Written for the test (issue 28): each task of the cell sets its own element of
    ! stReact; robot 1 asks a function whether all three read "Ready", and whether the
    ! gantry reports an error.
    PERS string stReact{3} := ["", "", ""];

    FUNC bool AllReady()
        RETURN stReact = ["Ready", "Ready", "Ready"];
    ENDFUNC

    FUNC bool GantryFailed()
        RETURN stReact{3} = "Error";
    ENDFUNC

    PROC main()
        WHILE TRUE DO
            stReact{1} := "Ready";
            WaitUntil AllReady() OR GantryFailed();
            stReact{1} := "Busy";
            WaitTime 0.5;
        ENDWHILE
    ENDPROC
ENDMODULE
