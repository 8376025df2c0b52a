MODULE Rob1
    ! Written for the test (issue 28): each task of the cell sets its own element of
    ! stReact; robot 1 goes on when all three elements read "Ready".
    PERS string stReact{3} := ["", "", ""];

    PROC main()
        WHILE TRUE DO
            stReact{1} := "Ready";
            WaitUntil stReact = ["Ready", "Ready", "Ready"];
            stReact{1} := "Busy";
            WaitTime 0.5;
        ENDWHILE
    ENDPROC
ENDMODULE
