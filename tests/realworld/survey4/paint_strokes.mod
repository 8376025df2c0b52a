MODULE PaintStrokes
    ! A panel painted in vertical strokes by a paint robot: PaintL moves like MoveL and
    ! SetBrush switches the brush at a coordinate. The spray gun and the panel's work
    ! object are taught in a calibration module that is not given here.
    LOCAL CONST robtarget pTop1 := [[500,-250,0],[0,0,1,0],[-1,1,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    LOCAL CONST robtarget pBottom1 := [[500,1050,0],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    LOCAL CONST robtarget pBottom2 := [[400,1050,0],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    LOCAL CONST robtarget pTop2 := [[400,-250,0],[0,0,1,0],[-1,1,-2,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR num panels := 0;

    PROC main()
        WHILE panels < 3 DO
            WaitDI diPanelReady, 1;
            PaintL pTop1, v800, z100, tSprayGun \WObj:=woPanel;
            SetBrush 3 \Y:=-100;
            SetBrush 1 \Y:=900;
            PaintL pBottom1, v800, z100, tSprayGun \WObj:=woPanel;
            PaintL pBottom2, v800, z100, tSprayGun \WObj:=woPanel;
            SetBrush 3 \Y:=900;
            PaintL pTop2, v800, z100, tSprayGun \WObj:=woPanel;
            PulseDO doPanelDone;
            panels := panels + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
